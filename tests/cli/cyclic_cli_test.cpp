// `brb cyclic` end to end: the real binary (BRB_CLI_PATH) run on temporary files. The brace is
// a short, stocky plate core (a few elements) so that each run takes a fraction of a second.
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"
#include "support/kinematic_bar.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace {

using brb::testing::CliRun;
using brb::testing::lines_of;
using brb::testing::numbers_of;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::run_brb_until_checkpoint;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;
using nlohmann::json;

namespace fs = std::filesystem;

// The test brace: a 12 x 10 mm plate, 100 mm long, fixed ends, S275 with the linear kinematic
// hardening of the Girona steel. Stocky enough (L / r = 35, effective length L / 2) not to
// buckle at 2 dy even at the hardening tangent.
constexpr double kYoungsModulus = 210000.0;     // MPa
constexpr double kYieldStress = 275.0;          // MPa
constexpr double kKinematicHardening = 21000.0; // MPa
constexpr double kPlateWidth = 12.0;            // mm
constexpr double kPlateDepth = 10.0;            // mm
constexpr double kCoreLength = 100.0;           // mm

/// The test brace; with `straight`, without the default bow imperfection (L / 1000).
json test_brace(bool straight = false) {
  json brace = {{"name", "stocky plate"},
                {"units", "mm"},
                {"core",
                 {{"section",
                   {{"shape", "rectangle"},
                    {"width", kPlateWidth},
                    {"depth", kPlateDepth},
                    {"fibers", {4, 4}}}},
                  {"steel",
                   {{"E", kYoungsModulus},
                    {"nu", 0.3},
                    {"fy", kYieldStress},
                    {"H_kin", kKinematicHardening},
                    {"H_iso", 0.0}}},
                  {"yielding_length", kCoreLength},
                  {"elements", 4}}},
                {"ends", "fixed"},
                {"casing", nullptr}};
  if (straight)
    brace["imperfection"] = {{"amplitude", 0.0}};
  return brace;
}

/// The bar's force under uniform strain through the closed-form uniaxial law of linear
/// kinematic hardening (tests/support/kinematic_bar.hpp).
std::vector<double> uniaxial_bar_forces(const std::vector<double>& deformations) {
  return brb::testing::KinematicBar{kYoungsModulus, kYieldStress, kKinematicHardening, kCoreLength,
                                    kPlateWidth * kPlateDepth}
      .forces(deformations);
}

/// Core only, no end zones: Py = fy A and dy = Py L / (E A) = fy L / E.
constexpr double kYieldForce = kYieldStress * kPlateWidth * kPlateDepth;
constexpr double kYieldDeformation = kYieldStress / kYoungsModulus * kCoreLength;

/// One cycle at 1 dy, then one at 2 dy, in steps of a quarter dy.
constexpr double kStepInDy = 0.25;
const std::vector<double> kAmplitudesInDy{1.0, 2.0};

json two_cycle_protocol() {
  json cycles = json::array();
  for (const double amplitude : kAmplitudesInDy)
    cycles.push_back({{"amplitude", amplitude}, {"cycles", 1}});
  return {{"units", "dy"}, {"cycles", cycles}, {"max_step", kStepInDy}};
}

const std::string kHysteresisHeader =
    "step,cycle,deformation,force,max_lateral_displacement,substeps";

std::string cyclic_arguments(const fs::path& brace, const fs::path& protocol,
                             const fs::path& output, const std::string& options = "") {
  return "cyclic " + shell_quoted(brace.string()) + " --protocol " +
         shell_quoted(protocol.string()) + " --out " + shell_quoted(output.string()) +
         (options.empty() ? "" : " " + options);
}

struct HysteresisRow {
  int step = 0;
  int cycle = 0;
  double deformation = 0.0;
  double force = 0.0;
  double max_lateral_displacement = 0.0;
  int substeps = 0;
};

/// The data rows of hysteresis.csv; the header must be exactly kHysteresisHeader.
std::vector<HysteresisRow> read_hysteresis(const fs::path& file) {
  const auto lines = lines_of(read_file(file));
  EXPECT_FALSE(lines.empty());
  if (lines.empty())
    return {};
  EXPECT_EQ(lines.front(), kHysteresisHeader);
  std::vector<HysteresisRow> rows;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto numbers = numbers_of(lines[i]);
    EXPECT_EQ(numbers.size(), 6u) << lines[i];
    if (numbers.size() != 6u)
      continue;
    rows.push_back({static_cast<int>(numbers[0]), static_cast<int>(numbers[1]), numbers[2],
                    numbers[3], numbers[4], static_cast<int>(numbers[5])});
    EXPECT_EQ(rows.back().step, numbers[0]) << "step is not a whole number: " << lines[i];
    EXPECT_EQ(rows.back().cycle, numbers[1]) << "cycle is not a whole number: " << lines[i];
  }
  return rows;
}

/// Work of the force over the increments into the rows accepted by `counts` (trapezoidal).
template <class Counts> double work_of(const std::vector<HysteresisRow>& rows, Counts counts) {
  double work = 0.0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (counts(rows[i])) {
      work += 0.5 * (rows[i].force + rows[i - 1].force) *
              (rows[i].deformation - rows[i - 1].deformation);
    }
  }
  return work;
}

std::set<std::string> keys_of(const json& object) {
  std::set<std::string> keys;
  for (const auto& item : object.items())
    keys.insert(item.key());
  return keys;
}

TEST(CyclicCli, HelpNamesEveryOption) {
  const CliRun top = run_brb("--help");
  EXPECT_EQ(top.exit_code, 0) << top.err;
  EXPECT_NE(top.out.find("cyclic"), std::string::npos) << top.out;

  const CliRun cyclic = run_brb("cyclic --help");
  EXPECT_EQ(cyclic.exit_code, 0) << cyclic.err;
  for (const char* word :
       {"--protocol", "--out", "--max-step", "--threads", "hysteresis.csv", "summary.json"})
    EXPECT_NE(cyclic.out.find(word), std::string::npos) << word << " not in:\n" << cyclic.out;
}

TEST(CyclicCli, ShortProtocolWritesHysteresisAndSummary) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace(/*straight=*/true).dump(2));
  const auto protocol = scratch.write("protocol.json", two_cycle_protocol().dump(2));
  const auto output = scratch.path() / "results"; // does not exist yet

  const CliRun run = run_brb(cyclic_arguments(brace, protocol, output));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const std::set<std::string> written{"hysteresis.csv", "summary.json"};
  std::set<std::string> found;
  for (const auto& entry : fs::directory_iterator(output))
    found.insert(entry.path().filename().string());
  EXPECT_EQ(found, written); // and no temporary file left

  // ---- hysteresis.csv ----
  const std::vector<HysteresisRow> rows = read_hysteresis(output / "hysteresis.csv");
  // 0 -> A -> -A -> 0 is 4 A of travel: 4 A / step points per cycle, plus the initial point.
  std::size_t expected_rows = 1;
  for (const double amplitude : kAmplitudesInDy)
    expected_rows += static_cast<std::size_t>(std::lround(4.0 * amplitude / kStepInDy));
  ASSERT_EQ(rows.size(), expected_rows);
  EXPECT_EQ(rows.front().step, 0);
  EXPECT_EQ(rows.front().cycle, 0);
  EXPECT_EQ(rows.front().deformation, 0.0);
  EXPECT_EQ(rows.front().force, 0.0);
  EXPECT_EQ(rows.back().deformation, 0.0);
  const double step_limit = kStepInDy * kYieldDeformation * (1.0 + 1e-9);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].step, static_cast<int>(i));
    EXPECT_TRUE(rows[i].cycle == rows[i - 1].cycle || rows[i].cycle == rows[i - 1].cycle + 1)
        << "row " << i;
    EXPECT_LE(std::abs(rows[i].deformation - rows[i - 1].deformation), step_limit) << "row " << i;
    EXPECT_GE(rows[i].substeps, 1) << "row " << i;
    EXPECT_GE(rows[i].max_lateral_displacement, 0.0) << "row " << i;
  }
  for (std::size_t cycle = 1; cycle <= kAmplitudesInDy.size(); ++cycle) {
    double largest = 0.0;
    double smallest = 0.0;
    for (const HysteresisRow& row : rows) {
      if (row.cycle == static_cast<int>(cycle)) {
        largest = std::max(largest, row.deformation);
        smallest = std::min(smallest, row.deformation);
      }
    }
    const double amplitude = kAmplitudesInDy[cycle - 1] * kYieldDeformation;
    EXPECT_NEAR(largest, amplitude, 1e-12 * amplitude) << "cycle " << cycle;
    EXPECT_NEAR(smallest, -amplitude, 1e-12 * amplitude) << "cycle " << cycle;
  }

  // ---- summary.json ----
  const json summary = json::parse(read_file(output / "summary.json"));
  EXPECT_EQ(keys_of(summary),
            (std::set<std::string>{"brace", "yield_deformation", "yield_force", "max_tension",
                                   "max_compression", "energy_total", "cycles", "completed",
                                   "stop_reason", "solver", "energy_balance", "element", "units"}));
  EXPECT_EQ(summary.at("brace"), "stocky plate");
  EXPECT_NEAR(summary.at("yield_force").get<double>(), kYieldForce, 1e-9 * kYieldForce);
  EXPECT_NEAR(summary.at("yield_deformation").get<double>(), kYieldDeformation,
              1e-12 * kYieldDeformation);
  EXPECT_EQ(summary.at("units"), (json{{"force", "N"}, {"length", "mm"}}));
  EXPECT_EQ(summary.at("completed"), true);
  EXPECT_TRUE(summary.at("stop_reason").is_null());

  // The summary's peaks and energies are those of the hysteresis it came with.
  const auto by_force = [](const HysteresisRow& a, const HysteresisRow& b) {
    return a.force < b.force;
  };
  const double max_tension = std::max_element(rows.begin(), rows.end(), by_force)->force;
  const double max_compression = std::min_element(rows.begin(), rows.end(), by_force)->force;
  EXPECT_EQ(summary.at("max_tension").get<double>(), max_tension);
  EXPECT_EQ(summary.at("max_compression").get<double>(), max_compression);
  const double total_work = work_of(rows, [](const HysteresisRow&) { return true; });
  EXPECT_NEAR(summary.at("energy_total").get<double>(), total_work, 1e-9 * std::abs(total_work));

  // Beyond dy the core yields both ways and hardens: the peaks pass Py.
  EXPECT_GT(max_tension, kYieldForce);
  EXPECT_LT(max_compression, -kYieldForce);

  const json& cycles = summary.at("cycles");
  ASSERT_TRUE(cycles.is_array());
  ASSERT_EQ(cycles.size(), kAmplitudesInDy.size());
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    const json& cycle = cycles[k];
    const int index = static_cast<int>(k) + 1;
    SCOPED_TRACE("cycle " + std::to_string(index));
    EXPECT_EQ(keys_of(cycle), (std::set<std::string>{"index", "amplitude", "energy", "max_tension",
                                                     "max_compression"}));
    EXPECT_EQ(cycle.at("index"), index);
    const double amplitude = kAmplitudesInDy[k] * kYieldDeformation;
    EXPECT_NEAR(cycle.at("amplitude").get<double>(), amplitude, 1e-12 * amplitude);
    const auto in_cycle = [index](const HysteresisRow& row) { return row.cycle == index; };
    const double work = work_of(rows, in_cycle);
    EXPECT_NEAR(cycle.at("energy").get<double>(), work, 1e-9 * kYieldForce * kYieldDeformation);
    double tension = 0.0;
    double compression = 0.0;
    for (const HysteresisRow& row : rows) {
      if (in_cycle(row)) {
        tension = std::max(tension, row.force);
        compression = std::min(compression, row.force);
      }
    }
    EXPECT_EQ(cycle.at("max_tension").get<double>(), tension);
    EXPECT_EQ(cycle.at("max_compression").get<double>(), compression);
  }
  // The straight bar under uniform strain is the uniaxial law: force and loop energies.
  std::vector<double> deformations;
  for (const HysteresisRow& row : rows)
    deformations.push_back(row.deformation);
  const std::vector<double> bar_forces = uniaxial_bar_forces(deformations);
  std::vector<HysteresisRow> bar = rows;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_NEAR(rows[i].force, bar_forces[i], 1e-6 * kYieldForce) << "row " << i;
    EXPECT_EQ(rows[i].max_lateral_displacement, 0.0) << "row " << i;
    bar[i].force = bar_forces[i];
  }
  for (std::size_t k = 0; k < cycles.size(); ++k) {
    const int index = static_cast<int>(k) + 1;
    const double bar_loop =
        work_of(bar, [index](const HysteresisRow& row) { return row.cycle == index; });
    EXPECT_NEAR(cycles[k].at("energy").get<double>(), bar_loop,
                1e-6 * kYieldForce * kYieldDeformation)
        << "cycle " << index;
  }
  // The cycle at 2 dy yields both ways; the one at 1 dy just reaches yield.
  EXPECT_GT(cycles[1].at("energy").get<double>(), cycles[0].at("energy").get<double>());

  const json& solver = summary.at("solver");
  EXPECT_EQ(keys_of(solver),
            (std::set<std::string>{
                "steps", "iterations", "substeps", "regularised_steps", "unstable_accepted",
                "energy_cuts", "energy_tolerance_missed", "far_branch_cuts", "assemblies",
                "line_search_assemblies", "converged_newton_iterations", "failed_newton_iterations",
                "failed_newton_calls", "pseudo_time_steps", "pseudo_time_iterations"}));
  EXPECT_EQ(solver.at("steps"), rows.size() - 1);
  EXPECT_GE(solver.at("substeps").get<int>(), solver.at("steps").get<int>());
  // (A straight uniform bar is in equilibrium after the predictor: no iteration is needed.)
  EXPECT_GE(solver.at("iterations").get<int>(), 0);
  EXPECT_GE(solver.at("regularised_steps").get<int>(), 0);
  EXPECT_GE(solver.at("unstable_accepted").get<int>(), 0);
  // every iteration is booked once, by outcome; each step assembles at least once
  EXPECT_EQ(solver.at("converged_newton_iterations").get<int>() +
                solver.at("failed_newton_iterations").get<int>() +
                solver.at("pseudo_time_iterations").get<int>(),
            solver.at("iterations").get<int>());
  EXPECT_GE(solver.at("assemblies").get<int>(), solver.at("steps").get<int>());

  const json& balance = summary.at("energy_balance");
  EXPECT_EQ(keys_of(balance),
            (std::set<std::string>{"external_work", "stored", "dissipated", "integration_misfit",
                                   "released_in_jumps", "released_by_laws", "gross_work",
                                   "relative_error", "law_relative_error", "relative_misfit"}));
  const double external_work = balance.at("external_work").get<double>();
  const double stored = balance.at("stored").get<double>();
  const double dissipated = balance.at("dissipated").get<double>();
  const double misfit = balance.at("integration_misfit").get<double>();
  const double released = balance.at("released_in_jumps").get<double>();
  const double released_by_laws = balance.at("released_by_laws").get<double>();
  const double gross_work = balance.at("gross_work").get<double>();
  const double relative_error = balance.at("relative_error").get<double>();
  EXPECT_GE(gross_work, std::abs(external_work));
  EXPECT_NEAR(relative_error,
              std::abs(external_work - stored - dissipated - misfit - released) / gross_work, 1e-9);
  EXPECT_NEAR(balance.at("law_relative_error").get<double>(),
              std::abs(external_work - stored - dissipated - released_by_laws) / gross_work, 1e-9);
  EXPECT_NEAR(balance.at("relative_misfit").get<double>(), std::abs(misfit) / gross_work, 1e-9);
  EXPECT_LT(relative_error, 1e-2); // a stable, converged solution balances its energy
  EXPECT_GT(dissipated, 0.0);

  // ---- the text summary ----
  for (const std::string& expected :
       {std::string("stocky plate"), (output / "hysteresis.csv").string(),
        (output / "summary.json").string(), std::string("completed")}) {
    EXPECT_NE(run.out.find(expected), std::string::npos) << expected << " not in:\n" << run.out;
  }
}

TEST(CyclicCli, HistoriesWriteTheElementOutputsAfterEveryStep) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace(/*straight=*/true).dump(2));
  const auto protocol = scratch.write("protocol.json", two_cycle_protocol().dump(2));
  const auto output = scratch.path() / "results";
  const CliRun run = run_brb(cyclic_arguments(brace, protocol, output, "--histories"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const std::vector<HysteresisRow> rows = read_hysteresis(output / "hysteresis.csv");
  const std::vector<std::string> lines = lines_of(read_file(output / "element_history.csv"));
  ASSERT_EQ(lines.size(), rows.size() + 1);
  EXPECT_EQ(lines.front(),
            "step,core_strain,dissipated_energy,cumulative_inelastic_deformation,"
            "max_core_lateral_displacement,max_casing_lateral_displacement,"
            "max_buckling_half_waves,max_steel_damage,max_mortar_damage,"
            "min_bearing_residual_strength,core_fracture,casing_failure,global_buckling");
  const json summary = json::parse(read_file(output / "summary.json"));
  std::vector<double> previous(13, 0.0);
  previous[9] = 1.0; // the residual strength starts intact
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const std::vector<double> values = numbers_of(lines[k]);
    ASSERT_EQ(values.size(), 13u) << lines[k];
    EXPECT_EQ(values[0], rows[k - 1].step);
    // Reference (theory): the straight core without end zones is the whole brace, so its
    // mean strain is the deformation over its length.
    EXPECT_NEAR(values[1], rows[k - 1].deformation / kCoreLength, 1e-9);
    // dissipation and the running maxima never decrease
    for (const std::size_t column : {2u, 3u, 4u, 6u, 7u}) {
      EXPECT_GE(values[column], previous[column] - 1e-9 * std::abs(previous[column]))
          << "column " << column << ", row " << k;
    }
    // the running minimum of the residual strength never increases, and stays in (0, 1]
    EXPECT_LE(values[9], previous[9]) << "row " << k;
    EXPECT_GT(values[9], 0.0) << "row " << k;
    previous = values;
  }
  // The last row holds what summary.json reports for the whole test.
  const json& element = summary.at("element");
  EXPECT_NEAR(previous[3], element.at("cumulative_inelastic_deformation").get<double>(), 1e-9);
  EXPECT_NEAR(previous[4], element.at("max_core_lateral_displacement").get<double>(), 1e-9);
  EXPECT_NEAR(previous[9], element.at("min_bearing_residual_strength").get<double>(), 1e-9);
  EXPECT_NEAR(previous[2],
              summary.at("energy_balance").at("dissipated").get<double>() +
                  summary.at("energy_balance").at("released_by_laws").get<double>(),
              1e-9 * previous[2]);
  EXPECT_GT(previous[2], 0.0);
  EXPECT_NE(run.out.find("element_history.csv"), std::string::npos) << run.out;
}

TEST(CyclicCli, ProgressPrintsALineAfterEveryStepAtIntervalZero) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace(/*straight=*/true).dump(2));
  const auto protocol = scratch.write("protocol.json", two_cycle_protocol().dump(2));
  const auto output = scratch.path() / "results";
  const CliRun run = run_brb(cyclic_arguments(brace, protocol, output, "--progress 0"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const std::vector<HysteresisRow> rows = read_hysteresis(output / "hysteresis.csv");
  std::vector<std::string> progress;
  for (const std::string& line : lines_of(run.err)) {
    if (line.rfind("brb: cyclic: step ", 0) == 0)
      progress.push_back(line);
  }
  // one line per step after the initial point, each naming the step, the total and the
  // step's deformation and force as hysteresis.csv has them
  const std::size_t steps = rows.size() - 1;
  ASSERT_EQ(progress.size(), steps) << run.err;
  long long previous_substeps = 0;
  for (std::size_t k = 1; k <= steps; ++k) {
    int step = 0, total = 0;
    long long substeps = 0;
    double percent = 0.0, deformation = 0.0, force = 0.0, seconds = 0.0;
    ASSERT_EQ(std::sscanf(progress[k - 1].c_str(),
                          "brb: cyclic: step %d of %d (%lf %%), deformation %lf mm, force %lf N, "
                          "%lld substeps, %lf s",
                          &step, &total, &percent, &deformation, &force, &substeps, &seconds),
              7)
        << progress[k - 1];
    EXPECT_EQ(step, static_cast<int>(k));
    EXPECT_EQ(total, static_cast<int>(steps));
    // printed to 0.1 %: off by at most half of that
    EXPECT_NEAR(percent, 100.0 * static_cast<double>(k) / static_cast<double>(steps), 0.05 + 1e-9);
    EXPECT_NEAR(deformation, rows[k].deformation, 5e-4 + 1e-3 * std::abs(rows[k].deformation));
    EXPECT_NEAR(force, rows[k].force, 0.5 + 1e-9 * std::abs(rows[k].force));
    // the running count of substeps grows by the step's own, as hysteresis.csv lists them
    EXPECT_EQ(substeps - previous_substeps, rows[k].substeps);
    previous_substeps = substeps;
    EXPECT_GE(seconds, 0.0);
  }
  EXPECT_NE(progress.back().find("(100.0 %)"), std::string::npos) << progress.back();
}

TEST(CyclicCli, ProgressMustBeANumberOfSeconds) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto protocol = scratch.write("protocol.json", two_cycle_protocol().dump());
  const auto output = scratch.path() / "results";
  for (const char* value : {"-1", "abc", "inf"}) {
    const CliRun run =
        run_brb(cyclic_arguments(brace, protocol, output, std::string("--progress=") + value));
    EXPECT_EQ(run.exit_code, 2) << value << ": " << run.err;
    EXPECT_NE(run.err.find("--progress"), std::string::npos) << run.err;
  }
  EXPECT_EQ(scratch.entries().size(), 2u); // nothing written
}

TEST(CyclicCli, ShapeStepsWriteTheDeformedBraceWithItsCasing) {
  // The source's small BRB (examples/braces/thesis_small_brb.json: a 10 x 10 mm core, 100 mm
  // long, 10 elements, in a mortar casing with a 0.05 mm gap), one cycle at 1 dy and one at
  // 3 dy in quarter-dy steps: step 52 is the 3 dy compression peak, where the core buckles
  // inside the gap and bears on the mortar.
  const ScratchDirectory scratch;
  const fs::path brace = fs::path(BRB_SOURCE_DIR) / "examples/braces/thesis_small_brb.json";
  const auto protocol = scratch.write(
      "protocol.json", json{{"units", "dy"},
                            {"cycles", json::array({json{{"amplitude", 1.0}, {"cycles", 1}},
                                                    json{{"amplitude", 3.0}, {"cycles", 1}}})},
                            {"max_step", 0.25}}
                           .dump());
  const auto output = scratch.path() / "results";
  const CliRun run = run_brb(cyclic_arguments(brace, protocol, output, "--shape-steps 52,0"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  EXPECT_NE(run.out.find("shape.csv"), std::string::npos) << run.out;
  const std::vector<HysteresisRow> hysteresis = read_hysteresis(output / "hysteresis.csv");
  ASSERT_EQ(hysteresis.size(), 65u); // 16 + 48 steps and the initial state
  ASSERT_LT(hysteresis[52].deformation, 0.0);
  const std::vector<std::string> lines = lines_of(read_file(output / "shape.csv"));
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.front(), "step,node,position,lateral_y,lateral_z,station,casing_lateral_y,"
                           "casing_lateral_z,bearing_force_y,bearing_force_z,mortar_damage,"
                           "friction_force,wave_normal_force,core_axial_force,"
                           "core_axial_strain,casing_axial_force");
  constexpr std::size_t kNodes = 11; // 10 core elements, no end zones
  // the asked steps in order, then the last converged one (64)
  ASSERT_EQ(lines.size(), 1 + 3 * kNodes);
  const double gap = 0.05; // mm, the brace file's
  const json summary = json::parse(read_file(output / "summary.json"));
  int bearing_stations = 0;
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const std::vector<double> row = numbers_of(lines[k]);
    ASSERT_EQ(row.size(), 16u) << lines[k];
    rows.push_back(row);
    const std::size_t block = (k - 1) / kNodes, node = (k - 1) % kNodes;
    EXPECT_EQ(row[0], (std::array{0.0, 52.0, 64.0}[block])) << lines[k];
    EXPECT_EQ(row[1], static_cast<double>(node)) << lines[k];
    // Reference (geometry): stations every 10 mm along the 100 mm core, all in the casing.
    EXPECT_NEAR(row[2], 10.0 * static_cast<double>(node), 1e-9) << lines[k];
    EXPECT_EQ(row[5], 1.0) << lines[k];
    if (block == 0) { // the unloaded initial state: nothing has moved, nothing bears
      for (const std::size_t column : {3u, 4u, 6u, 7u, 8u, 9u, 10u, 11u, 12u, 13u, 14u, 15u})
        EXPECT_EQ(row[column], 0.0) << "column " << column << ": " << lines[k];
    }
    // no node moves further than the summary's running maximum
    EXPECT_LE(std::hypot(row[3], row[4]),
              summary.at("element").at("max_core_lateral_displacement").get<double>() + 1e-9);
    // The mortar bears where the core has crossed the gap, pushing it back (the force on the
    // core opposes its motion relative to the casing).
    const double relative_y = row[3] - row[6];
    if (block == 1 && std::abs(relative_y) > gap) {
      EXPECT_LT(row[8] * relative_y, 0.0) << lines[k];
      ++bearing_stations;
    }
    EXPECT_GE(row[10], 0.0);
    EXPECT_LE(row[10], 1.0);
  }
  EXPECT_GT(bearing_stations, 0) << "the core does not reach the mortar at 3 dy compression";

  // Reference (statics, independent of the element formulation): the axial forces balance.
  // Columns: 11 friction on the core, 12 N_w, 13 core element's force, 14 its chord strain,
  // 15 casing beam's force.
  // Tolerance: the chord rotations (0.05 mm over 10 mm) tilt the elements' forces off the
  // axis by parts in 1e5 of the brace force.
  for (const std::size_t block : {1u, 2u}) {
    const double brace_force = hysteresis[block == 1 ? 52 : 64].force;
    const double tolerance = 2e-5 * std::abs(brace_force);
    const auto at = [&](std::size_t node) -> const std::vector<double>& {
      return rows[block * kNodes + node];
    };
    for (std::size_t node = 0; node + 1 < kNodes; ++node) {
      // Any section through core element `node` and casing beam `node` carries the brace force.
      EXPECT_NEAR(at(node)[13] + at(node)[15], brace_force, tolerance) << "node " << node;
      EXPECT_EQ(at(node)[12], 0.0) << "this brace has no sub-element waves";
      if (node > 0) { // a core node: the core's force changes by minus the friction on it
        EXPECT_NEAR(at(node)[13] - at(node - 1)[13] + at(node)[11], 0.0, tolerance)
            << "node " << node;
      }
    }
    // The casing has no axial support but the stopper (mid-length): at its first station
    // its beam carries exactly the friction there, which the core's end slides against in
    // the 3 dy compression.
    EXPECT_NEAR(at(0)[15], at(0)[11], tolerance);
    if (block == 1) {
      EXPECT_GT(std::abs(at(0)[11]), 10.0 * tolerance) << "no friction at the casing's end";
    }
  }

  // Reference (Hooke's law): at half the yield deformation (step 2, quarter-dy steps) the core
  // is elastic, so each element's force is E A times its chord strain (E = 210000 MPa,
  // A = 10 x 10 mm^2, the brace file's); the bow (0.1 mm) changes the chord strain by parts
  // in 1e5.
  const auto elastic_output = scratch.path() / "elastic";
  const CliRun elastic =
      run_brb(cyclic_arguments(brace, protocol, elastic_output, "--shape-steps 2"));
  ASSERT_EQ(elastic.exit_code, 0) << elastic.err << elastic.out;
  const std::vector<std::string> elastic_lines = lines_of(read_file(elastic_output / "shape.csv"));
  ASSERT_EQ(elastic_lines.size(), 1 + 2 * kNodes); // step 2, then the last step
  for (std::size_t node = 0; node + 1 < kNodes; ++node) {
    const std::vector<double> row = numbers_of(elastic_lines[1 + node]);
    ASSERT_EQ(row[0], 2.0);
    const double axial_stiffness = 210000.0 * 100.0; // N
    EXPECT_GT(row[13], 0.0) << "the cycle starts in tension: " << elastic_lines[1 + node];
    EXPECT_NEAR(row[13], axial_stiffness * row[14], 1e-4 * std::abs(row[13]))
        << elastic_lines[1 + node];
  }

  // a negative step is a usage error, and nothing is written
  const auto refused = scratch.path() / "refused";
  const CliRun bad = run_brb(cyclic_arguments(brace, protocol, refused, "--shape-steps 3,-1"));
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("--shape-steps"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(refused));
}

TEST(CyclicCli, TrussFidelityFollowsTheClosedFormBarLaw) {
  // "element": {"fidelity": "truss"}: one co-rotational truss with the uniaxial steel law
  // over the yielding length (no end zones here), so the force is the closed-form bar law
  // at delta / L at every row.
  const ScratchDirectory scratch;
  json brace = test_brace();
  brace["element"] = {{"fidelity", "truss"}, {"mode", "condensed"}};
  const auto brace_file = scratch.write("brace.json", brace.dump(2));
  const auto protocol = scratch.write("protocol.json", two_cycle_protocol().dump(2));
  const auto output = scratch.path() / "results";
  const CliRun run = run_brb(cyclic_arguments(brace_file, protocol, output));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const std::vector<HysteresisRow> rows = read_hysteresis(output / "hysteresis.csv");
  std::vector<double> deformations;
  for (const HysteresisRow& row : rows)
    deformations.push_back(row.deformation);
  const std::vector<double> bar_forces = uniaxial_bar_forces(deformations);
  ASSERT_GT(rows.size(), 10u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_NEAR(rows[i].force, bar_forces[i], 1e-9 * kYieldForce) << "row " << i;
    EXPECT_EQ(rows[i].max_lateral_displacement, 0.0);
  }
  const json summary = json::parse(std::ifstream(output / "summary.json"));
  EXPECT_NEAR(summary.at("yield_deformation").get<double>(),
              kYieldStress / kYoungsModulus * kCoreLength, 1e-12 * kCoreLength);
  EXPECT_FALSE(summary.at("element").at("global_buckling").get<bool>());
}

TEST(CyclicCli, CsvHistoryIsCutIntoStepsOfMaxStepAndReplacesPreviousResults) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto history = scratch.write("history.csv", "time,deformation\n1,0.2\n2,-0.2\n3,0\n");
  const auto output = scratch.path() / "results";
  fs::create_directory(output);
  const auto previous = scratch.write("results/summary.json", "previous results\n");
  constexpr double kMaxStep = 0.05; // mm

  const CliRun run =
      run_brb(cyclic_arguments(brace, history, output, "--max-step " + std::to_string(kMaxStep)));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(read_file(previous), "previous results\n");

  const std::vector<HysteresisRow> rows = read_hysteresis(output / "hysteresis.csv");
  // 0 -> 0.2 -> -0.2 -> 0 is 0.8 mm of travel.
  ASSERT_EQ(rows.size(), 1u + static_cast<std::size_t>(std::lround(0.8 / kMaxStep)));
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_LE(std::abs(rows[i].deformation - rows[i - 1].deformation), kMaxStep * (1.0 + 1e-9));
    EXPECT_EQ(rows[i].cycle, 1);
  }
  // The default bow (L / 1000) bends as the axial force changes.
  EXPECT_TRUE(std::any_of(rows.begin(), rows.end(), [](const HysteresisRow& row) {
    return row.max_lateral_displacement > 0.0;
  }));
  const json summary = json::parse(read_file(output / "summary.json"));
  ASSERT_EQ(summary.at("cycles").size(), 1u);
  EXPECT_EQ(summary.at("cycles")[0].at("amplitude").get<double>(), 0.2); // peak |deformation|
}

TEST(CyclicCli, StoppedAnalysisWritesWhatWasComputedAndExitsWithOne) {
  // A jump to 1e300 mm cannot be followed by any substepping (as in the `brb material` test):
  // the first step is computed, the second is not.
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto history = scratch.write("history.csv", "deformation\n0.1\n1e300\n");
  const auto output = scratch.path() / "results";

  const CliRun run = run_brb(cyclic_arguments(brace, history, output, "--max-step 1e300"));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(run.err.rfind("brb: error: " + history.string() + ": ", 0), 0u) << run.err;
  EXPECT_NE(run.err.find("stopped early"), std::string::npos) << run.err;

  const std::vector<HysteresisRow> rows = read_hysteresis(output / "hysteresis.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows.back().deformation, 0.1);
  const json summary = json::parse(read_file(output / "summary.json"));
  EXPECT_EQ(summary.at("completed"), false);
  ASSERT_TRUE(summary.at("stop_reason").is_string());
  EXPECT_FALSE(summary.at("stop_reason").get<std::string>().empty());
  EXPECT_NE(run.out.find(summary.at("stop_reason").get<std::string>()), std::string::npos)
      << run.out;
  EXPECT_EQ(summary.at("solver").at("steps"), 1);
}

// ---- Rejected inputs: exit 2, the message names the file and the JSON path, nothing written ----

struct BadRun {
  std::string name;
  json brace;
  std::string protocol;      ///< file contents
  std::string protocol_file; ///< its name (the extension chooses the reader)
  std::string file;          ///< the file the message must name: "brace" or "protocol"
  std::string where;         ///< the JSON path or CSV place the message must name
};

void PrintTo(const BadRun& bad, std::ostream* out) {
  *out << bad.name;
}

json brace_with(const json::json_pointer& pointer, const json& value) {
  json brace = test_brace();
  brace[pointer] = value;
  return brace;
}

const std::string kGoodProtocol = two_cycle_protocol().dump();

class CyclicRejected : public ::testing::TestWithParam<BadRun> {};

TEST_P(CyclicRejected, ExitsWithTwoNamesFileAndFieldAndWritesNothing) {
  const BadRun& bad = GetParam();
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", bad.brace.dump());
  const auto protocol = scratch.write(bad.protocol_file, bad.protocol);
  const auto output = scratch.path() / "results";

  const CliRun run = run_brb(cyclic_arguments(brace, protocol, output));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const std::string named = (bad.file == "brace" ? brace : protocol).string();
  EXPECT_EQ(run.err.rfind("brb: error: " + named + ": " + bad.where, 0), 0u) << run.err;
  EXPECT_FALSE(fs::exists(output));
  EXPECT_EQ(scratch.entries().size(), 2u); // only the inputs
  EXPECT_EQ(run.out, "");
}

INSTANTIATE_TEST_SUITE_P(
    EachKind, CyclicRejected,
    ::testing::Values(
        BadRun{"negative_length", brace_with(json::json_pointer("/core/yielding_length"), -100.0),
               kGoodProtocol, "protocol.json", "brace", "/core/yielding_length: "},
        BadRun{"zero_area", brace_with(json::json_pointer("/core/section/width"), 0.0),
               kGoodProtocol, "protocol.json", "brace", "/core/section/width: "},
        BadRun{"imperfection_longer_than_brace",
               brace_with(json::json_pointer("/imperfection"), {{"amplitude", 2.0 * kCoreLength}}),
               kGoodProtocol, "protocol.json", "brace", "/imperfection/amplitude: "},
        BadRun{"unknown_brace_key", brace_with(json::json_pointer("/colour"), "red"), kGoodProtocol,
               "protocol.json", "brace", "/colour: "},
        BadRun{"unknown_nested_brace_key", brace_with(json::json_pointer("/core/steel/Fy"), 275.0),
               kGoodProtocol, "protocol.json", "brace", "/core/steel/Fy: "},
        BadRun{"unknown_casing_key",
               brace_with(json::json_pointer("/casing"), {{"tube_wall", 3.0}}), kGoodProtocol,
               "protocol.json", "brace", "/casing/tube_wall: "},
        BadRun{"protocol_with_no_cycles", test_brace(), R"({"units": "dy", "cycles": []})",
               "protocol.json", "protocol", "/cycles: "},
        BadRun{"unknown_protocol_key", test_brace(),
               R"({"units": "dy", "cycles": [{"amplitude": 1, "cycles": 1}], "step": 0.1})",
               "protocol.json", "protocol", "/step: "},
        BadRun{"unknown_nested_protocol_key", test_brace(),
               R"({"units": "dy", "cycles": [{"amplitude": 1, "cycles": 1, "repeat": 2}]})",
               "protocol.json", "protocol", "/cycles/0/repeat: "},
        BadRun{"unitless_amplitudes", test_brace(),
               R"({"cycles": [{"amplitude": 1, "cycles": 1}]})", "protocol.json", "protocol",
               "/units: "},
        BadRun{"history_without_deformation", test_brace(), "strain\n0.001\n", "history.csv",
               "protocol", "line 1"}),
    [](const ::testing::TestParamInfo<BadRun>& info) { return info.param.name; });

TEST(CyclicCli, OutputDirectoryWhoseParentIsMissingIsAnInputError) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto protocol = scratch.write("protocol.json", kGoodProtocol);
  const auto output = scratch.path() / "missing" / "results";
  const CliRun run = run_brb(cyclic_arguments(brace, protocol, output));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.rfind("brb: error: " + output.string() + ": ", 0), 0u) << run.err;
  EXPECT_EQ(scratch.entries().size(), 2u);
}

TEST(CyclicCli, OutputPathThatIsAFileIsAnInputError) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto protocol = scratch.write("protocol.json", kGoodProtocol);
  const auto output = scratch.write("results", "a file\n");
  const CliRun run = run_brb(cyclic_arguments(brace, protocol, output));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_EQ(run.err.rfind("brb: error: " + output.string() + ": ", 0), 0u) << run.err;
  EXPECT_EQ(read_file(output), "a file\n");
  EXPECT_EQ(scratch.entries().size(), 3u);
}

TEST(CyclicCli, MaxStepMustBeAPositiveNumber) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto protocol = scratch.write("protocol.json", kGoodProtocol);
  const auto output = scratch.path() / "results";
  for (const char* value : {"0", "-0.1", "abc", "inf"}) {
    const CliRun run =
        run_brb(cyclic_arguments(brace, protocol, output, std::string("--max-step=") + value));
    EXPECT_EQ(run.exit_code, 2) << value << ": " << run.err;
    EXPECT_NE(run.err.find("--max-step"), std::string::npos) << run.err;
  }
  EXPECT_EQ(scratch.entries().size(), 2u);
}

TEST(CyclicCli, SolverTolerancesMustBeFractionsOfTheWork) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto protocol = scratch.write("protocol.json", kGoodProtocol);
  const auto output = scratch.path() / "results";
  for (const std::string option : {"--energy-tolerance", "--balance-tolerance"})
    for (const char* value : {"-1e-3", "1", "2.5", "abc"}) {
      const CliRun run = run_brb(cyclic_arguments(brace, protocol, output, option + "=" + value));
      EXPECT_EQ(run.exit_code, 2) << option << " " << value << ": " << run.err;
      EXPECT_NE(run.err.find(option), std::string::npos) << run.err;
      if (std::string(value) != "abc") { // a word is CLI11's conversion error
        EXPECT_NE(run.err.find(option + ": must be a number in [0, 1)"), std::string::npos)
            << run.err;
      }
    }
  EXPECT_EQ(scratch.entries().size(), 2u);
}

// --threads: the elements evaluated on threads give the same bytes as one thread; a count
// below 1 or a word is a usage error and writes nothing.
TEST(CyclicCli, ThreadsGiveTheSameOutputsAndMustBeAWholeNumberAtLeastOne) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto protocol = scratch.write("protocol.json", two_cycle_protocol().dump(2));
  const auto one = scratch.path() / "one";
  const auto two = scratch.path() / "two";
  const CliRun single = run_brb(cyclic_arguments(brace, protocol, one));
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const CliRun threaded = run_brb(cyclic_arguments(brace, protocol, two, "--threads 2"));
  ASSERT_EQ(threaded.exit_code, 0) << threaded.err;
  EXPECT_EQ(read_file(two / "hysteresis.csv"), read_file(one / "hysteresis.csv"));
  const auto bad_output = scratch.path() / "bad";
  for (const char* value : {"0", "-1", "two"}) {
    const CliRun run =
        run_brb(cyclic_arguments(brace, protocol, bad_output, std::string("--threads=") + value));
    EXPECT_EQ(run.exit_code, 2) << value << ": " << run.err;
    EXPECT_NE(run.err.find("--threads"), std::string::npos) << run.err;
  }
  EXPECT_FALSE(fs::exists(bad_output));
}

TEST(CyclicCli, MissingArgumentsAndFilesAreUsageOrInputErrors) {
  const ScratchDirectory scratch;
  const auto brace = scratch.write("brace.json", test_brace().dump());
  const auto protocol = scratch.write("protocol.json", kGoodProtocol);
  const auto output = scratch.path() / "results";

  const CliRun no_protocol =
      run_brb("cyclic " + shell_quoted(brace.string()) + " --out " + shell_quoted(output.string()));
  EXPECT_EQ(no_protocol.exit_code, 2);
  EXPECT_NE(no_protocol.err.find("--protocol"), std::string::npos) << no_protocol.err;

  const auto absent = scratch.path() / "absent.json";
  const CliRun no_brace = run_brb(cyclic_arguments(absent, protocol, output));
  EXPECT_EQ(no_brace.exit_code, 2);
  EXPECT_EQ(no_brace.err.rfind("brb: error: " + absent.string() + ": ", 0), 0u) << no_brace.err;
  EXPECT_EQ(scratch.entries().size(), 2u);
}

// --checkpoint: a run killed after writing its checkpoint is taken up by the next run with
// the same files and settings and ends with the outputs of a run that never stopped (the same
// bytes); a file that is not a checkpoint of this run is refused before anything is written.
// The brace is the source's small BRB of case 3 (validation/thesis_small_case3), whose core
// buckles in the casing's gap: a few seconds per run.
TEST(CyclicCli, ARunKilledAfterACheckpointIsTakenUpToTheSameOutputs) {
  const fs::path specimen = fs::path(BRB_SOURCE_DIR) / "validation" / "thesis_small_case3";
  const std::string inputs = shell_quoted((specimen / "brace.json").string()) + " --protocol " +
                             shell_quoted((specimen / "protocol.json").string());
  const ScratchDirectory scratch;
  const fs::path reference = scratch.path() / "reference";
  const fs::path resumed = scratch.path() / "resumed";
  const fs::path checkpoint = scratch.path() / "run.checkpoint";
  const CliRun whole = run_brb("cyclic " + inputs + " --out " + shell_quoted(reference.string()));
  ASSERT_EQ(whole.exit_code, 0) << whole.err;

  // started with a checkpoint after every step, killed once one is written
  ASSERT_TRUE(run_brb_until_checkpoint(
      "cyclic " + inputs + " --out " + shell_quoted(resumed.string()) + " --checkpoint " +
          shell_quoted(checkpoint.string()) + " --checkpoint-every 1e-9",
      checkpoint))
      << "no checkpoint written";
  ASSERT_FALSE(fs::exists(resumed / "hysteresis.csv")) << "the run ended before it was killed";

  const CliRun taken_up = run_brb("cyclic " + inputs + " --out " + shell_quoted(resumed.string()) +
                                  " --checkpoint " + shell_quoted(checkpoint.string()));
  ASSERT_EQ(taken_up.exit_code, 0) << taken_up.err;
  EXPECT_NE(taken_up.err.find("taking up the run from the checkpoint " + checkpoint.string()),
            std::string::npos)
      << taken_up.err;
  EXPECT_FALSE(fs::exists(checkpoint)) << "the checkpoint stays once the outputs are written";
  EXPECT_EQ(read_file(resumed / "hysteresis.csv"), read_file(reference / "hysteresis.csv"));
  const json summary = json::parse(read_file(resumed / "summary.json"));
  const json reference_summary = json::parse(read_file(reference / "summary.json"));
  EXPECT_GE(summary["solver"]["resumed_from_step"].get<int>(), 1);
  EXPECT_EQ(summary["energy_balance"], reference_summary["energy_balance"]);
  EXPECT_EQ(summary["solver"]["iterations"], reference_summary["solver"]["iterations"]);
  EXPECT_FALSE(reference_summary["solver"].contains("resumed_from_step"));
}

TEST(CyclicCli, AFileThatIsNotACheckpointOfTheRunIsRefusedBeforeAnythingIsWritten) {
  const ScratchDirectory scratch;
  const fs::path brace = scratch.write("brace.json", test_brace().dump());
  const fs::path protocol = scratch.write(
      "protocol.json", R"({"units": "mm", "cycles": [{"amplitude": 0.2, "cycles": 1}]})");
  const fs::path checkpoint = scratch.write("run.checkpoint", "step,deformation\n0,0\n");
  const fs::path out = scratch.path() / "out";
  const CliRun run =
      run_brb("cyclic " + shell_quoted(brace.string()) + " --protocol " +
              shell_quoted(protocol.string()) + " --out " + shell_quoted(out.string()) +
              " --checkpoint " + shell_quoted(checkpoint.string()));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find(checkpoint.string() + ": not a checkpoint of brb cyclic"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::exists(checkpoint)) << "a refused checkpoint is left as it was";

  const CliRun bad_interval = run_brb("cyclic " + shell_quoted(brace.string()) + " --protocol " +
                                      shell_quoted(protocol.string()) + " --out " +
                                      shell_quoted(out.string()) + " --checkpoint-every 0");
  EXPECT_EQ(bad_interval.exit_code, 2);
  EXPECT_NE(bad_interval.err.find("--checkpoint-every"), std::string::npos) << bad_interval.err;
}

} // namespace
