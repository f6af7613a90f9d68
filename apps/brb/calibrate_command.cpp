#include "calibrate_command.hpp"

#include "brb/io/atomic_file.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/force_record.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"
#include "brb/validation/record_comparison.hpp"
#include "brb/validation/record_protocol.hpp"
#include "brb/validation/specimen.hpp"
#include "brb/validation/steel_calibration.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

namespace brb::cli {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

/// The steel object of the brace schema (README "Brace files", core.steel).
Json steel_json(const material::SteelParameters& steel) {
  Json object;
  object["units"] = "MPa";
  object["E"] = steel.youngs_modulus;
  object["nu"] = steel.poissons_ratio;
  object["fy"] = steel.yield_stress;
  object["H_kin"] = steel.kinematic_hardening;
  object["H_iso"] = steel.isotropic_hardening;
  Json chaboche = Json::array();
  for (const auto& term : steel.chaboche)
    chaboche.push_back({{"C", term.modulus}, {"gamma", term.recall}});
  object["chaboche"] = chaboche;
  object["voce"] = {{"Q", steel.voce_saturation}, {"b", steel.voce_rate}};
  if (steel.damage) {
    object["fu"] = steel.damage->onset_stress;
    object["Gf"] = steel.damage->fracture_energy;
  }
  return object;
}

/// The record reference in the JSON file: its "reference" member (a metrics.json) or the
/// whole document.
io::ForceRecordReference read_reference(const fs::path& file,
                                        const std::optional<fs::path>& shared_option) {
  const nlohmann::json document = io::read_json_file(file);
  const io::JsonValue root(document, file.string());
  const fs::path base = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  fs::path shared;
  if (shared_option) {
    shared = *shared_option;
  } else if (const auto found = io::find_shared_directory(base)) {
    shared = *found;
  }
  const io::JsonValue reference =
      document.is_object() && document.contains("reference") ? *root.find("reference") : root;
  const std::string file_name =
      reference.json().is_object() ? reference.json().value("file", std::string()) : std::string();
  if (file_name.starts_with("shared:") && shared.empty()) {
    throw reference.error("a \"shared:\" path, but no ancestor of the file's directory has a "
                          "'shared' directory: give --shared DIR");
  }
  // any reference type of a metrics.json (lab_record by default, solid_run, solver_csv, with
  // its stated failure), read as brb validate reads it
  return validation::read_record_reference(reference, base, shared).source;
}

} // namespace

CLI::App* add_calibrate_command(CLI::App& app, CalibrateCommand& command) {
  auto* calibrate = app.add_subcommand(
      "calibrate", "Calibrate a brace's core steel (fy, 2 Chaboche terms, Voce) on a laboratory "
                   "force-deformation record with the fast axial model of the brace.");
  calibrate->add_option("brace", command.brace, "Brace file (geometry and starting steel)")
      ->type_name("BRACE.json")
      ->required();
  calibrate
      ->add_option("--record", command.record,
                   "JSON file with the record reference: a validation metrics.json (its "
                   "\"reference\", of any type: lab_record, solid_run, solver_csv) or a bare "
                   "reference object {file, columns, units, exclude_rows}")
      ->type_name("RECORD.json")
      ->required();
  calibrate->add_option("--out", command.output, "Calibrated parameters and errors (JSON)")
      ->type_name("PARAMS.json")
      ->required();
  calibrate->add_option("--protocol-out", command.protocol_output,
                        "Also write the protocol extracted from the record (columns "
                        "deformation, mm, and record_row, -1 where not a record point)");
  calibrate->add_option("--shared", command.shared_directory,
                        "Directory that \"shared:\" record paths name (default: the first "
                        "ancestor's 'shared' folder)");
  calibrate
      ->add_option("--side", command.side,
                   "Test points the objective uses: tension (test force >= 0, default) "
                   "or all")
      ->check(CLI::IsMember({"tension", "all"}));
  calibrate
      ->add_option("--max-evaluations", command.max_evaluations,
                   "Most objective evaluations (0: evaluate the brace's steel only)")
      ->check(CLI::NonNegativeNumber);
  calibrate
      ->add_option("--reversal-threshold", command.reversal_threshold,
                   "Reversal noise threshold, in dy (default 0.1)")
      ->check(CLI::PositiveNumber);
  calibrate
      ->add_option("--max-step", command.max_step,
                   "Largest protocol step, in dy (default 0.0999, under brb cyclic's dy/10)")
      ->check(CLI::PositiveNumber);
  calibrate
      ->add_option("--energy-floor", command.energy_floor,
                   "Cycles below this fraction of the largest test loop energy are not "
                   "scored (default 0.05)")
      ->check(CLI::Range(0.0, 1.0));
  return calibrate;
}

int run_calibrate_command(const CalibrateCommand& command, std::ostream& report) {
  const model::BraceSpec brace = io::read_brace(command.brace);
  const io::ForceRecordReference reference =
      read_reference(command.record, command.shared_directory);
  const io::ForceRecord record = io::read_force_record(reference.file, reference.format);

  const validation::AxialBraceIdealisation axial = validation::AxialBraceIdealisation::of(brace);
  const double dy = axial.yield_deformation(brace.steel.yield_stress);
  const validation::RecordProtocol protocol = validation::extract_record_protocol(
      record.deformation, {command.reversal_threshold * dy, command.max_step * dy});

  std::vector<double> test_force(protocol.size(), 0.0);
  std::vector<bool> compared(protocol.size(), false);
  for (std::size_t k = 0; k < protocol.size(); ++k) {
    if (protocol.record_index[k] != validation::RecordProtocol::kNoRecordPoint) {
      test_force[k] = record.force[protocol.record_index[k]];
      compared[k] = true;
    }
  }

  validation::CalibrationOptions options;
  options.side = command.side == "all" ? validation::CalibrationSide::all
                                       : validation::CalibrationSide::tension;
  options.max_evaluations = command.max_evaluations;
  const validation::CalibrationResult result = validation::calibrate_steel(
      brace.steel, axial, protocol.deformation, test_force, compared, options);

  // The three record metrics of the fast model, over the compared points.
  std::vector<double> deformation_c, test_c, model_c;
  for (std::size_t k = 0; k < protocol.size(); ++k) {
    if (compared[k]) {
      deformation_c.push_back(protocol.deformation[k]);
      test_c.push_back(test_force[k]);
      model_c.push_back(result.model_force[k]);
    }
  }
  // beta on the cycles whose test peaks reach Py = fy A_c, as brb validate compares
  const double yield_force = brace.steel.yield_stress * axial.core_area;
  const validation::RecordComparison comparison = validation::compare_with_record(
      deformation_c, test_c, model_c,
      {command.reversal_threshold * dy, command.energy_floor, yield_force});

  Json output;
  output["steel"] = steel_json(result.steel);
  Json& calibration = output["calibration"];
  calibration["brace"] = command.brace.string();
  calibration["record"] = reference.file.string();
  calibration["record_rows_kept"] = record.size();
  calibration["yield_deformation_mm"] = dy;
  calibration["protocol_points"] = protocol.size();
  calibration["compared_points"] = deformation_c.size();
  calibration["side"] = command.side;
  calibration["evaluations"] = result.evaluations;
  calibration["start_error"] = result.start_objective;
  calibration["normalised_rms_error"] = result.error_all;
  calibration["normalised_rms_error_tension"] = result.error_tension;
  calibration["scored_cycles"] = comparison.scored_cycles;
  calibration["max_cycle_energy_error"] = comparison.max_cycle_energy_error;
  calibration["max_beta_difference"] = comparison.max_beta_difference;
  calibration["beta_cycles"] = comparison.beta_cycles;
  calibration["model"] = "fast axial model: yielding core (SteelUniaxial) in series with "
                         "elastic end zones; no buckling, contact or friction";

  if (command.protocol_output) {
    io::NumericTable table({"deformation", "record_row"});
    for (std::size_t k = 0; k < protocol.size(); ++k) {
      const std::size_t index = protocol.record_index[k];
      const double row = index == validation::RecordProtocol::kNoRecordPoint
                             ? -1.0
                             : static_cast<double>(record.row[index]);
      const double values[] = {protocol.deformation[k], row};
      table.append_row(values);
    }
    io::write_file_atomically(*command.protocol_output, table.text());
  }
  io::write_file_atomically(command.output, output.dump(2) + "\n");

  report << "brb calibrate: brace " << command.brace.string() << ", record "
         << reference.file.string() << " (" << record.size() << " rows kept)\n"
         << "  dy = " << dy << " mm; protocol " << protocol.size() << " points, "
         << deformation_c.size() << " compared, " << protocol.reversal_points.size()
         << " reversals\n"
         << "  objective (" << command.side << " side): " << result.start_objective << " -> "
         << result.objective << " after " << result.evaluations << " evaluations\n"
         << "  normalised RMS force error: all points " << result.error_all << ", tension side "
         << result.error_tension << "\n"
         << "  cycles scored " << comparison.scored_cycles << ": max loop-energy error "
         << comparison.max_cycle_energy_error << ", max |beta difference| "
         << comparison.max_beta_difference << " (" << comparison.beta_cycles
         << " cycles whose test peaks reach Py both ways)\n"
         << "  steel: " << steel_json(result.steel).dump() << "\n"
         << "  wrote " << command.output.string() << "\n";
  return 0;
}

} // namespace brb::cli
