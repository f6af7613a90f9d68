#include "material_command.hpp"

#include "brb/analysis/material_driver.hpp"
#include "brb/io/atomic_file.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/material_input.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace brb::cli {
namespace {

using material::LongElementRule;

enum class MaterialLaw { steel, steel3d_collapsed, mortar, mortar3d_collapsed };

struct LawName {
  std::string_view name;
  MaterialLaw law;
};

constexpr std::array kLawNames{
    LawName{"steel", MaterialLaw::steel},
    LawName{"steel3d-collapsed", MaterialLaw::steel3d_collapsed},
    LawName{"mortar", MaterialLaw::mortar},
    LawName{"mortar3d-collapsed", MaterialLaw::mortar3d_collapsed},
};

MaterialLaw law_named(std::string_view name) {
  const auto entry = std::find_if(kLawNames.begin(), kLawNames.end(),
                                  [name](const LawName& law) { return law.name == name; });
  if (entry == kLawNames.end())
    throw std::invalid_argument("unknown law " + std::string(name));
  return entry->law;
}

/// The material point of `law` with the parameters of `file`, built with
/// LongElementRule::reject: an lc too long for the softening is an input error.
analysis::UniaxialMaterialPoint make_material_point(MaterialLaw law,
                                                    const std::filesystem::path& file) {
  using Point = analysis::UniaxialMaterialPoint;
  switch (law) {
  case MaterialLaw::steel:
  case MaterialLaw::steel3d_collapsed: {
    const io::SteelInput input = io::read_steel_input(file);
    const double lc = input.characteristic_length_for_law();
    return io::build_checked(input.source, [&]() -> Point {
      if (law == MaterialLaw::steel) {
        return material::SteelUniaxial(input.parameters, lc, LongElementRule::reject);
      }
      return analysis::CollapsedSteel(
          material::SteelDamagePlasticity3D(input.parameters, lc, LongElementRule::reject));
    });
  }
  case MaterialLaw::mortar:
  case MaterialLaw::mortar3d_collapsed: {
    const io::MortarInput input = io::read_mortar_input(file);
    const double lc = input.characteristic_length;
    return io::build_checked(input.source, [&]() -> Point {
      if (law == MaterialLaw::mortar) {
        return material::MortarUniaxial(input.parameters, lc, LongElementRule::reject);
      }
      return analysis::CollapsedMortar(
          material::MortarDamage3D(input.parameters, lc, LongElementRule::reject));
    });
  }
  }
  throw std::logic_error("make_material_point: unhandled law");
}

/// The output's directory must exist: say so as an input error rather than fail to write.
void check_output_directory(const std::filesystem::path& output) {
  const auto directory = output.parent_path();
  if (output.filename().empty()) {
    throw io::InputError(output.string(), "", "--out must name a file, not a directory");
  }
  if (!directory.empty() && !std::filesystem::is_directory(directory)) {
    throw io::InputError(output.string(), "",
                         "cannot write the output: directory '" + directory.string() +
                             "' does not exist");
  }
}

} // namespace

CLI::App* add_material_command(CLI::App& app, MaterialCommand& command) {
  auto* material = app.add_subcommand(
      "material", "Drive one material point through a strain history and write its response.");
  std::vector<std::string> law_names;
  for (const auto& law : kLawNames)
    law_names.emplace_back(law.name);
  material
      ->add_option("--law", command.law,
                   "Material law: steel (closed-form uniaxial steel), steel3d-collapsed (3D "
                   "steel law collapsed to a fiber by local Newton), mortar (closed-form "
                   "uniaxial mortar), mortar3d-collapsed (3D mortar law collapsed to a fiber)")
      ->required()
      ->check(CLI::IsMember(law_names));
  material
      ->add_option("--params", command.parameters,
                   "Material parameters, JSON (comments allowed); keys in the README")
      ->required();
  material
      ->add_option("--strain", command.strain_history,
                   "Strain history, CSV with a header and a column 'strain' (other columns "
                   "ignored)")
      ->required();
  material
      ->add_option("--out", command.output,
                   "Output CSV: strain,stress,tangent,damage (MPa), one row per history row")
      ->required();
  material->footer(
      "Parameter keys (README, \"brb material\"):\n"
      "  steel, steel3d-collapsed: E, nu, fy, H_kin, H_iso; optional chaboche [{C, gamma}] (at\n"
      "    most 4), voce {Q, b}; damage: Gf with fu and lc; units \"MPa\" (optional)\n"
      "  mortar, mortar3d-collapsed: E, nu, fc, ft, Gf, lc; units \"MPa\" (optional)\n"
      "Units: N, mm, s, MPa. Exit status: 0 success, 1 run failed, 2 invalid input or usage.");
  return material;
}

int run_material_command(const MaterialCommand& command, std::ostream& notes) {
  const MaterialLaw law = law_named(command.law);
  const analysis::UniaxialMaterialPoint point = make_material_point(law, command.parameters);
  const io::NumericColumn history = io::read_numeric_column(command.strain_history, "strain");
  check_output_directory(command.output);

  analysis::MaterialPathResult path;
  try {
    path = analysis::drive_strain_path(point, history.values);
  } catch (const analysis::MaterialPathFailure& failure) {
    throw std::runtime_error(command.strain_history.string() + ": line " +
                             std::to_string(history.lines.at(failure.row())) + ": " + command.law +
                             ": " + failure.what());
  }

  io::NumericTable table({"strain", "stress", "tangent", "damage"});
  for (const auto& point_response : path.points) {
    table.append_row(std::array{point_response.strain, point_response.stress,
                                point_response.tangent, point_response.damage});
  }
  io::write_file_atomically(command.output, table.text());

  if (path.substepped_increments > 0) {
    notes << "brb material: " << path.substepped_increments << " of " << path.points.size()
          << " rows needed substepping (at most " << path.most_substeps
          << " substeps per increment)\n";
  }
  return 0;
}

} // namespace brb::cli
