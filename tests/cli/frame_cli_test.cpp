// `brb frame` end to end: the real binary (BRB_CLI_PATH) on the example buildings of frames/
// and on a one-storey portal frame written by the test, under the shared ground-motion records.
// Each run takes about a second or less.
#include "cli/run_brb.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <ostream>
#include <string>
#include <vector>

namespace {

using brb::testing::CliRun;
using brb::testing::lines_of;
using brb::testing::numbers_of;
using brb::testing::read_file;
using brb::testing::run_brb;
using brb::testing::ScratchDirectory;
using brb::testing::shell_quoted;
using nlohmann::json;

namespace fs = std::filesystem;

const fs::path kFrames = fs::path(BRB_SOURCE_DIR) / "frames";
const fs::path kGroundMotions = fs::path(BRB_SHARED_DIR) / "data" / "ground_motions";
const fs::path kElCentro = kGroundMotions / "elCentro.AT2";
const fs::path kRinaldi = kGroundMotions / "Rinaldi228.AT2";

std::string frame_arguments(const fs::path& model, const fs::path& motion, const fs::path& output,
                            const std::string& options = "") {
  return "frame " + shell_quoted(model.string()) + " --motion " + shell_quoted(motion.string()) +
         " --out " + shell_quoted(output.string()) + (options.empty() ? "" : " " + options);
}

/// A CSV history written by `brb frame`: its header and its rows of numbers.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;

  std::size_t column(const std::string& name) const {
    const auto found = std::find(columns.begin(), columns.end(), name);
    EXPECT_NE(found, columns.end()) << "no column " << name;
    return static_cast<std::size_t>(found - columns.begin());
  }
  /// max |value| of a column over the rows.
  double peak(const std::string& name) const {
    const std::size_t c = column(name);
    double peak = 0.0;
    for (const auto& row : rows)
      peak = std::max(peak, std::abs(row.at(c)));
    return peak;
  }
};

Table read_table(const fs::path& file) {
  Table table;
  const auto lines = lines_of(read_file(file));
  EXPECT_FALSE(lines.empty()) << file;
  if (lines.empty())
    return table;
  std::string header = lines.front();
  for (std::size_t comma; (comma = header.find(',')) != std::string::npos;) {
    table.columns.push_back(header.substr(0, comma));
    header.erase(0, comma + 1);
  }
  table.columns.push_back(header);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    table.rows.push_back(numbers_of(lines[i]));
    EXPECT_EQ(table.rows.back().size(), table.columns.size()) << file << ": " << lines[i];
  }
  return table;
}

json read_json(const fs::path& file) {
  return json::parse(read_file(file));
}

// ---- The 3-storey example building (frames/brbf3) under the first 3 s of El Centro ----

TEST(FrameCli, Brbf3ShortRunWritesTheSummaryAndTheRecordedHistories) {
  const ScratchDirectory scratch;
  const auto output = scratch.path() / "brbf3";
  const CliRun run =
      run_brb(frame_arguments(kFrames / "brbf3" / "model.json", kElCentro, output, "--duration 3"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  EXPECT_EQ(run.err, "");

  // The model's recorders ask for every history; summary.json is written last.
  std::vector<std::string> written;
  for (const auto& entry : fs::directory_iterator(output))
    written.push_back(entry.path().filename().string());
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written,
            (std::vector<std::string>{"base_shear.csv", "braces.csv", "drifts.csv", "energy.csv",
                                      "floor_accelerations.csv", "summary.json"}));

  const json summary = read_json(output / "summary.json");
  const auto stories = summary.at("stories").get<std::vector<std::string>>();
  ASSERT_EQ(stories.size(), 3u); // brbf3: three storeys
  const auto max_drift = summary.at("max_drift").get<std::vector<double>>();
  const auto residual_drift = summary.at("residual_drift").get<std::vector<double>>();
  ASSERT_EQ(max_drift.size(), stories.size());
  ASSERT_EQ(residual_drift.size(), stories.size());
  EXPECT_TRUE(summary.at("converged").get<bool>());
  EXPECT_FALSE(summary.at("collapse").get<bool>());
  EXPECT_EQ(summary.at("stop_reason"), "completed");
  EXPECT_TRUE(summary.at("fallbacks").is_array());
  EXPECT_EQ(summary.at("integrator"), "newmark");
  const double energy_input = summary.at("energy_input").get<double>();
  EXPECT_GT(energy_input, 0.0);
  // A converged Newmark run balances its energy (README "Energy balance"); 1 % of the input.
  EXPECT_LT(summary.at("energy_balance_error").get<double>(), 0.01);
  const auto periods = summary.at("periods").get<std::vector<double>>();
  ASSERT_FALSE(periods.empty());
  EXPECT_GT(periods.front(), 0.0);
  EXPECT_TRUE(std::is_sorted(periods.rbegin(), periods.rend())) << "periods not in mode order";

  // --duration 3 keeps floor(3 / 0.02) + 1 samples of the record (dt 0.02 s): 3 s, analysed in
  // the model's steps of 0.005 s: 600 steps.
  EXPECT_DOUBLE_EQ(summary.at("duration").get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(summary.at("end_time").get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(summary.at("dt").get<double>(), 0.005);
  const int steps = summary.at("steps").get<int>();
  EXPECT_EQ(steps, 600);
  // one row per recorded state: the gravity state at t = 0, then every step
  const std::size_t recorded = static_cast<std::size_t>(steps) + 1;

  const Table drifts = read_table(output / "drifts.csv");
  ASSERT_EQ(drifts.columns.size(), 1 + stories.size());
  EXPECT_EQ(drifts.columns.front(), "time");
  ASSERT_EQ(drifts.rows.size(), recorded);
  EXPECT_DOUBLE_EQ(drifts.rows.back().front(), 3.0);
  for (std::size_t s = 0; s < stories.size(); ++s) {
    const std::string column = "drift_x_" + stories[s];
    // Recomputed from the CSV (full-precision numbers in both files). A planar drift is
    // along x only, so the summary's drift magnitudes are |drift_x|; the residual drift is the
    // last recorded one.
    EXPECT_DOUBLE_EQ(std::abs(drifts.rows.back().at(drifts.column(column))), residual_drift[s])
        << column;
    EXPECT_DOUBLE_EQ(drifts.peak(column), max_drift[s]) << column;
    // El Centro's first 3 s push the frame's braces past yield, not to collapse.
    EXPECT_GT(max_drift[s], 1e-3) << column;
    EXPECT_LT(max_drift[s], 0.1) << column;
  }

  const Table base_shear = read_table(output / "base_shear.csv");
  EXPECT_EQ(base_shear.columns, (std::vector<std::string>{"time", "base_shear_x"}));
  EXPECT_EQ(base_shear.rows.size(), recorded);
  EXPECT_DOUBLE_EQ(base_shear.peak("base_shear_x"), summary.at("peak_base_shear").get<double>());

  const auto floors = summary.at("floors").get<std::vector<std::string>>();
  const auto peak_acceleration = summary.at("peak_floor_acceleration_g").get<std::vector<double>>();
  ASSERT_EQ(peak_acceleration.size(), floors.size());
  const Table accelerations = read_table(output / "floor_accelerations.csv");
  EXPECT_EQ(accelerations.rows.size(), recorded);
  for (std::size_t f = 0; f < floors.size(); ++f) {
    const std::string column = "accel_x_" + floors[f] + "_g";
    EXPECT_DOUBLE_EQ(accelerations.peak(column), peak_acceleration[f]) << column;
  }

  const Table energy = read_table(output / "energy.csv");
  EXPECT_EQ(energy.columns,
            (std::vector<std::string>{"time", "input", "static_work", "kinetic", "damping",
                                      "stored", "dissipated", "integration_misfit", "error"}));
  ASSERT_EQ(energy.rows.size(), recorded);
  const auto& last_energy = energy.rows.back();
  // error = input + static work - kinetic - damping - stored - dissipated - misfit (README
  // "brb frame", energy.csv), summed here from the written columns
  const auto value = [&](const std::string& name) { return last_energy.at(energy.column(name)); };
  EXPECT_NEAR(value("error"),
              value("input") + value("static_work") - value("kinetic") - value("damping") -
                  value("stored") - value("dissipated") - value("integration_misfit"),
              1e-9 * std::abs(value("input")));
  EXPECT_DOUBLE_EQ(value("integration_misfit"),
                   summary.at("energy").at("integration_misfit").get<double>());
  EXPECT_DOUBLE_EQ(last_energy.at(energy.column("input")), energy_input);
  // energy_balance_error = |error| / input at the end (README "brb frame")
  EXPECT_NEAR(std::abs(last_energy.at(energy.column("error"))) / energy_input,
              summary.at("energy_balance_error").get<double>(), 1e-12);

  // braces.csv: one row per recorded state and brace ("braces": "all": the six brb elements).
  const json braces = summary.at("braces");
  ASSERT_EQ(braces.size(), 6u);
  const Table brace_history = read_table(output / "braces.csv");
  EXPECT_EQ(brace_history.columns,
            (std::vector<std::string>{"time", "brace", "force", "deformation", "core_strain", "cid",
                                      "steel_damage", "mortar_damage", "core_fracture",
                                      "casing_failure", "global_buckling"}));
  EXPECT_EQ(brace_history.rows.size(), recorded * braces.size());
  const std::size_t id_column = brace_history.column("brace");
  const std::size_t force_column = brace_history.column("force");
  for (const json& brace : braces) {
    const int id = brace.at("id").get<int>();
    std::size_t rows = 0;
    double tension = 0.0, compression = 0.0; // the summary's peaks start at 0
    for (const auto& row : brace_history.rows) {
      if (row.at(id_column) != id)
        continue;
      ++rows;
      tension = std::max(tension, row.at(force_column));
      compression = std::max(compression, -row.at(force_column));
    }
    EXPECT_EQ(rows, recorded) << "brace " << id;
    EXPECT_DOUBLE_EQ(tension, brace.at("max_tension").get<double>()) << "brace " << id;
    EXPECT_DOUBLE_EQ(compression, brace.at("max_compression").get<double>()) << "brace " << id;
  }
}

// ---- A one-storey portal frame written by the test ----

/// Two fixed-base columns, a beam (elastic_beam, linear geometry) and, with `braced`, an
/// elastic diagonal truss; 20 t on each top node, 2 % Rayleigh damping, no gravity.
json portal_frame(bool braced) {
  json elements = json::array(
      {{{"id", 1}, {"type", "elastic_beam"}, {"nodes", {1, 11}}, {"section", "COLUMN"}},
       {{"id", 2}, {"type", "elastic_beam"}, {"nodes", {2, 12}}, {"section", "COLUMN"}},
       {{"id", 3}, {"type", "elastic_beam"}, {"nodes", {11, 12}}, {"section", "BEAM"}}});
  if (braced) {
    elements.push_back(
        {{"id", 4}, {"type", "truss"}, {"nodes", {1, 12}}, {"area", 1000}, {"material", "brace"}});
  }
  return {
      {"title", "portal"},
      {"dimension", 2},
      {"nodes",
       {{{"id", 1}, {"xyz", {0, 0, 0}}},
        {{"id", 2}, {"xyz", {6000, 0, 0}}},
        {{"id", 11}, {"xyz", {0, 0, 4000}}},
        {{"id", 12}, {"xyz", {6000, 0, 4000}}}}},
      {"supports", {{{"node", 1}, {"fix", "fixed"}}, {{"node", 2}, {"fix", "fixed"}}}},
      {"masses", {{{"node", 11}, {"mass", 20.0}}, {{"node", 12}, {"mass", 20.0}}}},
      {"sections",
       {{"COLUMN",
         {{"E", 200000}, {"G", 77000}, {"A", 10000}, {"Iy", 2e8}, {"Iz", 2e7}, {"J", 6e5}}},
        {"BEAM",
         {{"E", 200000}, {"G", 77000}, {"A", 10000}, {"Iy", 5e8}, {"Iz", 2e7}, {"J", 6e5}}}}},
      {"materials", {{"brace", {{"law", "elastic"}, {"E", 200000}}}}},
      {"elements", elements},
      {"damping", {{"type", "rayleigh"}, {"modes", {1, 2}}, {"ratios", {0.02, 0.02}}}},
      {"analysis", {{"integrator", "newmark"}, {"dt", 0.01}}},
      {"stories", {{{"name", "1"}, {"bottom", 1}, {"top", 11}}}},
      {"floors", {{{"name", "roof"}, {"node", 11}}}},
      {"recorders",
       {{"drifts", true}, {"floor_accelerations", true}, {"base_shear", true}, {"energy", true}}}};
}

TEST(FrameCli, ScaleTwoDoublesTheDriftsOfALinearFrame) {
  // The unbraced portal is a linear system: elastic beams of linear geometry, no gravity, linear
  // viscous damping, starting at rest. Newmark's average-acceleration steps are then linear in
  // the ground acceleration, so doubling the record doubles every displacement; the only
  // difference is round-off and the Newton tolerance (a linear step converges in one
  // iteration). (The braced portal would not do: the truss is co-rotational, geometrically
  // nonlinear.)
  const ScratchDirectory scratch;
  const auto model = scratch.write("portal.json", portal_frame(false).dump());
  const auto once = scratch.path() / "once";
  const auto twice = scratch.path() / "twice";
  const CliRun run_once = run_brb(frame_arguments(model, kElCentro, once, "--duration 1"));
  ASSERT_EQ(run_once.exit_code, 0) << run_once.err << run_once.out;
  const CliRun run_twice =
      run_brb(frame_arguments(model, kElCentro, twice, "--duration 1 --scale 2"));
  ASSERT_EQ(run_twice.exit_code, 0) << run_twice.err << run_twice.out;

  const json summary_once = read_json(once / "summary.json");
  const json summary_twice = read_json(twice / "summary.json");
  EXPECT_EQ(summary_twice.at("scale").get<double>(), 2.0);
  const double peak_once = summary_once.at("max_drift").at(0).get<double>();
  const double peak_twice = summary_twice.at("max_drift").at(0).get<double>();
  ASSERT_GT(peak_once, 0.0);
  EXPECT_NEAR(peak_twice / peak_once, 2.0, 1e-6);

  // ... and so is every recorded drift, step by step.
  const Table drifts_once = read_table(once / "drifts.csv");
  const Table drifts_twice = read_table(twice / "drifts.csv");
  ASSERT_EQ(drifts_once.rows.size(), 101u); // 1 s in steps of 0.01 s, and t = 0
  ASSERT_EQ(drifts_twice.rows.size(), drifts_once.rows.size());
  const std::size_t column = drifts_once.column("drift_x_1");
  for (std::size_t i = 0; i < drifts_once.rows.size(); ++i) {
    EXPECT_NEAR(drifts_twice.rows[i].at(column), 2.0 * drifts_once.rows[i].at(column),
                1e-6 * peak_once)
        << "t = " << drifts_once.rows[i].front();
  }
}

TEST(FrameCli, StepOverridesTheModelsTimeStep) {
  // --step replaces the model's analysis.dt: the run takes that step (summary "dt") and the
  // histories have one row per step (1 s at 0.005 s: 200 steps and t = 0); the peak drift is
  // that of the same linear system at a finer step, so it stays within a few percent of the
  // model's own step (Newmark's average acceleration has no amplitude error, a period error
  // of order (omega dt)^2 / 12).
  const ScratchDirectory scratch;
  const auto model = scratch.write("portal.json", portal_frame(false).dump());
  const auto own = scratch.path() / "own";
  const auto finer = scratch.path() / "finer";
  const CliRun run_own = run_brb(frame_arguments(model, kElCentro, own, "--duration 1"));
  ASSERT_EQ(run_own.exit_code, 0) << run_own.err << run_own.out;
  const CliRun run_finer =
      run_brb(frame_arguments(model, kElCentro, finer, "--duration 1 --step 0.005"));
  ASSERT_EQ(run_finer.exit_code, 0) << run_finer.err << run_finer.out;
  const json summary_own = read_json(own / "summary.json");
  const json summary_finer = read_json(finer / "summary.json");
  EXPECT_EQ(summary_own.at("dt").get<double>(), portal_frame(false).at("analysis").at("dt"));
  EXPECT_EQ(summary_finer.at("dt").get<double>(), 0.005);
  EXPECT_EQ(read_table(finer / "drifts.csv").rows.size(), 201u);
  const double peak_own = summary_own.at("max_drift").at(0).get<double>();
  const double peak_finer = summary_finer.at("max_drift").at(0).get<double>();
  ASSERT_GT(peak_own, 0.0);
  EXPECT_NEAR(peak_finer / peak_own, 1.0, 0.05);
}

TEST(FrameCli, CoreElementsOverrideEveryBracesMeshAndTheSummarySaysSo) {
  // brbf3's brace files mesh their cores with 16 elements; --core-elements 2 builds the full
  // braces with 2 (a short elastic window: about a second). The summary records the count, or
  // null when the files' own were used (the committed runs of brb bench pareto are checked
  // against it).
  const ScratchDirectory scratch;
  const auto coarse = scratch.path() / "coarse";
  const CliRun run = run_brb(frame_arguments(kFrames / "brbf3" / "model.json", kElCentro, coarse,
                                             "--duration 0.03 --braces full --core-elements 2"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const json summary = read_json(coarse / "summary.json");
  EXPECT_EQ(summary.at("core_elements").get<int>(), 2);
  for (const auto& brace : summary.at("braces"))
    EXPECT_EQ(brace.at("fidelity").get<std::string>(), "full");
  const auto own = scratch.path() / "own";
  const CliRun truss = run_brb(frame_arguments(kFrames / "brbf3" / "model.json", kElCentro, own,
                                               "--duration 0.03 --braces truss"));
  ASSERT_EQ(truss.exit_code, 0) << truss.err << truss.out;
  EXPECT_TRUE(read_json(own / "summary.json").at("core_elements").is_null());
}

TEST(FrameCli, ProgressLinesSayWhereALongRunStands) {
  // --progress S: a line on stderr at most every S seconds of run time (the default, 30 s, says
  // nothing in a short run: Brbf3ShortRunWritesTheSummaryAndTheRecordedHistories checks an
  // empty stderr). With a microsecond every step reports: 1 s of the portal at dt 0.01 s.
  const ScratchDirectory scratch;
  const auto model = scratch.write("portal.json", portal_frame(false).dump());
  const auto output = scratch.path() / "results";
  const CliRun run =
      run_brb(frame_arguments(model, kElCentro, output, "--duration 1 --progress 0.000001"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const auto lines = lines_of(run.err);
  ASSERT_EQ(lines.size(), 100u) << run.err;
  EXPECT_EQ(lines.front().rfind("brb frame: t = 0.010 of 1.000 s (step 1 of 100), peak drift ", 0),
            0u)
      << lines.front();
  EXPECT_NE(lines.front().find(" min left"), std::string::npos);
  EXPECT_EQ(lines.back().rfind("brb frame: t = 1.000 of 1.000 s (step 100 of 100)", 0), 0u)
      << lines.back();
  EXPECT_EQ(lines.back().find(" min left"), std::string::npos); // nothing left
  // the peak drift reported at the end is the summary's, in percent
  const double peak = read_json(output / "summary.json").at("max_drift").at(0).get<double>();
  std::ostringstream percent;
  percent << std::fixed << std::setprecision(2) << 100.0 * peak << " %";
  EXPECT_NE(lines.back().find("peak drift " + percent.str()), std::string::npos) << lines.back();
}

// ---- Rejected inputs: exit 2, the message names the file and the place, nothing written ----

enum class Motion { el_centro, missing, non_numeric };

struct BadFrameRun {
  std::string name;
  json model;
  Motion motion = Motion::el_centro;
  std::string options; ///< more command-line options
  std::string named;   ///< what the message must name: "model", "motion", "command line", "out"
  std::string where;   ///< the text after "brb: error: <named>: "
  bool missing_parent = false; ///< --out inside a directory that does not exist
};

void PrintTo(const BadFrameRun& bad, std::ostream* out) {
  *out << bad.name;
}

json portal_with(const json::json_pointer& pointer, const json& value) {
  json model = portal_frame(true);
  model[pointer] = value;
  return model;
}

/// A PEER AT2 record of 4 values whose fourth is not a number.
const std::string kNonNumericRecord = "PEER test record\n"
                                      "made up\n"
                                      "ACCELERATION TIME SERIES IN UNITS OF G\n"
                                      "NPTS=   4, DT=   .0100 SEC\n"
                                      "  0.01  0.02\n"
                                      "  0.03  abc\n";

class FrameRejected : public ::testing::TestWithParam<BadFrameRun> {};

TEST_P(FrameRejected, ExitsWithTwoNamesFileAndPlaceAndWritesNothing) {
  const BadFrameRun& bad = GetParam();
  const ScratchDirectory scratch;
  const auto model = scratch.write("frame.json", bad.model.dump());
  std::size_t inputs = 1;
  fs::path motion = kElCentro;
  if (bad.motion == Motion::missing) {
    motion = scratch.path() / "none.AT2";
  } else if (bad.motion == Motion::non_numeric) {
    motion = scratch.write("record.AT2", kNonNumericRecord);
    ++inputs;
  }
  const auto output =
      bad.missing_parent ? scratch.path() / "missing" / "results" : scratch.path() / "results";

  const CliRun run = run_brb(frame_arguments(model, motion, output, bad.options));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  const std::string named = bad.named == "model"    ? model.string()
                            : bad.named == "motion" ? motion.string()
                            : bad.named == "out"    ? output.string()
                                                    : bad.named;
  EXPECT_EQ(run.err.rfind("brb: error: " + named + ": " + bad.where, 0), 0u) << run.err;
  EXPECT_FALSE(fs::exists(output));
  EXPECT_EQ(scratch.entries().size(), inputs); // only the inputs: no output directory
  EXPECT_EQ(run.out, "");
}

INSTANTIATE_TEST_SUITE_P(
    EachKind, FrameRejected,
    ::testing::Values(
        BadFrameRun{"dangling_node", portal_with(json::json_pointer("/elements/0/nodes/1"), 99),
                    Motion::el_centro, "", "model",
                    "/elements/0/nodes/1: element 1 refers to node 99"},
        BadFrameRun{"no_masses", portal_with(json::json_pointer("/masses"), json::array()),
                    Motion::el_centro, "", "model", "/masses: zero mass with a dynamic analysis"},
        BadFrameRun{"unknown_element_type",
                    portal_with(json::json_pointer("/elements/3/type"), "cable"), Motion::el_centro,
                    "", "model", "/elements/3/type: unknown element type \"cable\""},
        BadFrameRun{"duplicate_node_id", portal_with(json::json_pointer("/nodes/3/id"), 11),
                    Motion::el_centro, "", "model", "/nodes/3/id: duplicate node id 11"},
        BadFrameRun{"zero_dt", portal_with(json::json_pointer("/analysis/dt"), 0),
                    Motion::el_centro, "", "model", "/analysis/dt: time step dt must be > 0 s"},
        BadFrameRun{"negative_dt", portal_with(json::json_pointer("/analysis/dt"), -0.01),
                    Motion::el_centro, "", "model", "/analysis/dt: time step dt must be > 0 s"},
        BadFrameRun{"missing_motion", portal_frame(true), Motion::missing, "", "motion",
                    "cannot read the file: it does not exist"},
        BadFrameRun{"non_numeric_motion", portal_frame(true), Motion::non_numeric, "", "motion",
                    "line 6: "},
        BadFrameRun{"zero_scale", portal_frame(true), Motion::el_centro, "--scale 0",
                    "command line", "--scale: must be a finite number other than 0"},
        BadFrameRun{"zero_step", portal_frame(true), Motion::el_centro, "--step 0", "command line",
                    "--step: must be a finite time step > 0 s"},
        BadFrameRun{"zero_core_elements", portal_frame(true), Motion::el_centro,
                    "--core-elements 0", "command line",
                    "--core-elements: must be a whole number from 1 to 4096"},
        BadFrameRun{"negative_progress", portal_frame(true), Motion::el_centro,
                    "--progress -1", "command line",
                    "--progress: must be a finite number of seconds >= 0"},
        BadFrameRun{"missing_output_parent", portal_frame(true), Motion::el_centro, "", "out",
                    "cannot create the output directory: its parent", true}),
    [](const ::testing::TestParamInfo<BadFrameRun>& info) { return info.param.name; });

TEST(FrameCli, AnExistingOutputDirectoryStaysEmptyAfterAnInputError) {
  const ScratchDirectory scratch;
  const auto model = scratch.write(
      "frame.json", portal_with(json::json_pointer("/elements/0/nodes/1"), 99).dump());
  const auto output = scratch.path() / "results";
  fs::create_directory(output);
  const CliRun run = run_brb(frame_arguments(model, kElCentro, output));
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_TRUE(fs::is_directory(output));
  EXPECT_TRUE(fs::is_empty(output));
}

TEST(FrameCli, ThePortalTheRejectionsEditIsValid) {
  // The model the rejected inputs edit is itself valid: each rejection is its one edit's.
  const ScratchDirectory scratch;
  const auto model = scratch.write("frame.json", portal_frame(true).dump());
  const auto output = scratch.path() / "results";
  const CliRun run = run_brb(frame_arguments(model, kElCentro, output, "--duration 0.5"));
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const json summary = read_json(output / "summary.json");
  EXPECT_TRUE(summary.at("converged").get<bool>());
  EXPECT_DOUBLE_EQ(summary.at("end_time").get<double>(), 0.5);
}

// ---- Collapse: the 9-storey building under 8 x Rinaldi ----

TEST(FrameCli, Brbf9UnderEightTimesRinaldiCollapsesAndStopsAtTheDriftLimit) {
  const ScratchDirectory scratch;
  const auto output = scratch.path() / "brbf9";
  const CliRun run =
      run_brb(frame_arguments(kFrames / "brbf9" / "model.json", kRinaldi, output, "--scale 8"));
  // A collapse is a result, not a failure: exit 0 and every output written.
  ASSERT_EQ(run.exit_code, 0) << run.err << run.out;
  const json summary = read_json(output / "summary.json");
  EXPECT_TRUE(summary.at("collapse").get<bool>());
  EXPECT_NE(summary.at("stop_reason").get<std::string>().find("collapse"), std::string::npos)
      << summary.at("stop_reason");
  const double end_time = summary.at("end_time").get<double>();
  EXPECT_LT(end_time, summary.at("duration").get<double>());
  const auto max_drift = summary.at("max_drift").get<std::vector<double>>();
  EXPECT_GT(*std::max_element(max_drift.begin(), max_drift.end()), 0.1); // drift_limit 0.1

  // The run stops at the first step beyond the limit: only the last recorded state has a
  // story drift above 10 %.
  const Table drifts = read_table(output / "drifts.csv");
  ASSERT_EQ(drifts.rows.size(), static_cast<std::size_t>(summary.at("steps").get<int>()) + 1);
  const auto largest_drift = [](const std::vector<double>& row) {
    double largest = 0.0;
    for (std::size_t c = 1; c < row.size(); ++c) // column 0 is the time
      largest = std::max(largest, std::abs(row[c]));
    return largest;
  };
  EXPECT_DOUBLE_EQ(drifts.rows.back().front(), end_time);
  EXPECT_GT(largest_drift(drifts.rows.back()), 0.1);
  for (std::size_t i = 0; i + 1 < drifts.rows.size(); ++i)
    ASSERT_LE(largest_drift(drifts.rows[i]), 0.1) << "t = " << drifts.rows[i].front();
}

TEST(FrameCli, AGravityLoadThatFailsIsReportedWithExitOne) {
  // The portal made of trusses on pinned supports is a mechanism (its node rotations and its
  // sway have no stiffness): the gravity steps fail after every fallback. The run says so
  // (exit 1, summary.json with converged false and no drifts, since no step was taken).
  json mechanism = portal_frame(false);
  for (json& element : mechanism["elements"]) {
    element = {{"id", element["id"]},
               {"type", "truss"},
               {"nodes", element["nodes"]},
               {"area", 1000},
               {"material", "brace"}};
  }
  mechanism["supports"] = {{{"node", 1}, {"fix", "pinned"}}, {{"node", 2}, {"fix", "pinned"}}};
  mechanism["gravity"] = {{"from_masses", true}};
  const ScratchDirectory scratch;
  const auto model = scratch.write("mechanism.json", mechanism.dump());
  const auto output = scratch.path() / "results";
  const CliRun run = run_brb(frame_arguments(model, kElCentro, output, "--duration 0.1"));
  ASSERT_EQ(run.exit_code, 1) << run.err << run.out;
  EXPECT_NE(run.err.find("gravity"), std::string::npos) << run.err;
  const json summary = read_json(output / "summary.json");
  EXPECT_FALSE(summary.at("converged").get<bool>());
  EXPECT_NE(summary.at("stop_reason").get<std::string>().find("gravity"), std::string::npos);
  EXPECT_TRUE(summary.at("max_drift").empty());
  EXPECT_EQ(summary.at("steps").get<int>(), 0);
}

} // namespace
