// The reference types of metrics.json (issue 6, item 6): a `brb solid` run directory and an
// external 3D solver's CSV, compared with the model through the record metrics. The
// references are made from a known model run (its own hysteresis, re-exported with renamed
// columns, in kN and inches), so every error is zero by construction; a force shifted by a
// constant gives the normalised RMS error of its definition; the failure mode and cycle are
// judged within one cycle; bad columns, units and types are refused at their JSON path.
#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/cyclic_output.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_model.hpp"
#include "brb/validation/failure_mode.hpp"
#include "brb/validation/specimen.hpp"
#include "brb/validation/specimen_run.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using brb::io::InputError;
using brb::testing::read_file;
using brb::testing::ScratchDirectory;
using brb::validation::CheckResult;
using brb::validation::CheckStatus;
using brb::validation::FailureEvent;
using brb::validation::FailureMode;
using brb::validation::PreparedSpecimen;
using brb::validation::RunData;
using brb::validation::Specimen;
using nlohmann::json;

// The bare plate core of the examples (Py = 275 x 400 = 110000 N), coarser (6 elements,
// 4 x 2 fibers) to run in about half a second, through two cycles at 0.5 dy and two at 1 dy,
// in steps of 0.25 dy (49 points). Bare, the plate buckles as a whole in compression once it
// yields (global_buckling, in the first cycle at 1 dy: cycle 3).
constexpr const char* kProtocol = R"({"units": "dy", "max_step": 0.25,
  "cycles": [{"amplitude": 0.5, "cycles": 2}, {"amplitude": 1, "cycles": 2}]})";

/// Newtons per kN and millimetres per inch, the units of the solver export.
constexpr double kNewtonsPerKilonewton = 1000.0;
constexpr double kMillimetresPerInch = 25.4;

/// The model run every reference is made from, shared by the tests (one analysis).
struct ModelRun {
  brb::analysis::CyclicTestResult result;
  double yield_deformation = 0.0;
  double yield_force = 0.0;
  double yielding_length = 0.0;
};

class ReferenceTypes : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    const brb::io::LoadingProtocol protocol = write_brace_and_protocol();
    brb::model::BraceModel brace = brb::model::build_brace_model(spec());
    run_->result = brb::analysis::run_cyclic_test(brace, protocol.deformation, protocol.cycle,
                                                  protocol.cycle_amplitude, {}, true);
  }

  /// The brace and protocol files in a fresh scratch directory, and the run's dy, Py and
  /// yielding length; returns the protocol as `brb validate` reads it (prepare_specimen:
  /// default step dy / 10, here the protocol's own 0.25 dy).
  static brb::io::LoadingProtocol write_brace_and_protocol() {
    scratch_ = std::make_unique<ScratchDirectory>();
    json brace =
        brb::io::read_json_file(fs::path(BRB_SOURCE_DIR) / "examples/braces/plate_core_bare.json");
    brace["core"]["elements"] = 6;
    brace["core"]["section"]["fibers"] = {4, 2};
    scratch_->write("brace.json", brace.dump(2));
    scratch_->write("protocol.json", kProtocol);
    const brb::model::BraceModel model = brb::model::build_brace_model(spec());
    run_ = std::make_unique<ModelRun>();
    run_->yield_deformation = model.yield_deformation;
    run_->yield_force = model.yield_force;
    run_->yielding_length = spec().yielding_length;
    return brb::io::read_protocol(scratch_->path() / "protocol.json", model.yield_deformation,
                                  model.yield_deformation / 10);
  }

  static brb::model::BraceSpec spec() { return brb::io::read_brace(root() / "brace.json"); }

  static void TearDownTestSuite() {
    run_.reset();
    scratch_.reset();
  }

  static const ModelRun& run() { return *run_; }
  static const fs::path& root() { return scratch_->path(); }

  /// The model's failure (the run recorded its history, so it is known).
  static FailureEvent model_failure() {
    const auto failure = brb::validation::model_failure(run().result);
    EXPECT_TRUE(failure.has_value());
    return failure.value_or(FailureEvent{});
  }

  /// A `brb solid`-like run directory holding the model run's hysteresis.csv and summary.json.
  static fs::path write_solid_run(const std::string& name) {
    const fs::path directory = root() / name;
    fs::create_directories(directory);
    scratch_->write(name + "/hysteresis.csv", brb::io::hysteresis_table(run().result).text());
    scratch_->write(name + "/summary.json",
                    brb::io::cyclic_summary_json("plate", run().yield_deformation,
                                                 run().yield_force, run().result)
                        .dump(2));
    return directory;
  }

  /// The model run re-exported as a solver would: columns in another order and named its own
  /// way, force in kN and deformation in inches, a time column, force + `shift` (N).
  static fs::path write_solver_csv(const std::string& name, double shift = 0.0,
                                   double deformation_scale = 1.0) {
    std::string text = "Time [s],RF1 [kN],U1 [in]\n";
    for (const brb::analysis::CyclicStep& step : run().result.steps) {
      text += brb::io::format_number(0.01 * step.step) + "," +
              brb::io::format_number((step.force + shift) / kNewtonsPerKilonewton) + "," +
              brb::io::format_number(deformation_scale * step.deformation / kMillimetresPerInch) +
              "\n";
    }
    return scratch_->write(name, text);
  }

  static json solver_reference(const std::string& file) {
    return {{"type", "solver_csv"},
            {"file", "../" + file},
            {"columns", {{"deformation", "U1 [in]"}, {"force", "RF1 [kN]"}, {"time", "Time [s]"}}},
            {"units", {{"force", "kN"}, {"length", "in"}}}};
  }

  static json failure_of(const FailureEvent& event) {
    json failure = {{"failure_mode", std::string(brb::validation::to_string(event.mode))}};
    if (event.mode != FailureMode::none)
      failure["cycle"] = event.cycle;
    return failure;
  }

  /// A metric with a reference of 0 and an absolute tolerance.
  static json zero_metric(const std::string& name, const std::string& kind, double tolerance) {
    return {{"name", name},
            {"kind", kind},
            {"reference", 0.0},
            {"tolerance", {{"absolute", tolerance}}}};
  }

  /// Specimen folder `id` (brace and protocol of the model run) with `reference` and
  /// `metrics`; returns its folder.
  static fs::path write_specimen(const std::string& id, const json& reference, const json& metrics,
                                 const json& comparison = nullptr) {
    fs::create_directories(root() / id);
    scratch_->write(id + "/brace.json", read_file(root() / "brace.json"));
    scratch_->write(id + "/protocol.json", kProtocol);
    json document = {{"id", id},
                     {"title", "reference type test"},
                     {"source", "test"},
                     {"brace", "brace.json"},
                     {"protocol", "protocol.json"},
                     {"refinements", {1}},
                     {"reference", reference},
                     {"metrics", metrics}};
    if (!comparison.is_null())
      document["comparison"] = comparison;
    scratch_->write(id + "/metrics.json", document.dump(2));
    return root() / id;
  }

  /// The metric checks (automatic checks left out) of the model run against the specimen.
  static std::vector<CheckResult> metric_checks(const fs::path& folder) {
    const PreparedSpecimen prepared =
        brb::validation::prepare_specimen(brb::validation::read_specimen(folder, root()));
    EXPECT_TRUE(prepared.record.has_value());
    const RunData data{run().result, run().yield_deformation, run().yield_force,
                       run().yielding_length, &*prepared.record};
    std::vector<CheckResult> checks = brb::validation::evaluate_checks(prepared.specimen, data);
    // the automatic ones: completion, energy balance, integration misfit
    checks.erase(checks.begin(), checks.begin() + 3);
    return checks;
  }

  static std::unique_ptr<ScratchDirectory> scratch_;
  static std::unique_ptr<ModelRun> run_;
};

std::unique_ptr<ScratchDirectory> ReferenceTypes::scratch_;
std::unique_ptr<ModelRun> ReferenceTypes::run_;

/// Every metric kind of the comparison, each expecting 0 within `tolerance`, and the failure.
json every_metric(double tolerance) {
  json metrics = json::array();
  for (const char* kind : {"record_nrms", "record_cycle_energy"})
    metrics.push_back({{"name", kind},
                       {"kind", kind},
                       {"reference", 0.0},
                       {"tolerance", {{"absolute", tolerance}}}});
  // beta of a named cycle: the worst-cycle form compares only cycles whose peaks reach Py
  // both ways, and the bare plate buckles below Py in compression (none here)
  metrics.push_back({{"name", "beta of compared cycle 3"},
                     {"kind", "record_beta"},
                     {"compared_cycle", 3},
                     {"reference", 0.0},
                     {"tolerance", {{"absolute", tolerance}}}});
  metrics.push_back({{"name", "peak tension and compression"},
                     {"kind", "record_peak_force"},
                     {"reference", 0.0},
                     {"tolerance", {{"absolute", tolerance}}}});
  metrics.push_back({{"name", "peak compression of compared cycle 3"},
                     {"kind", "record_peak_force"},
                     {"direction", "compression"},
                     {"compared_cycle", 3},
                     {"reference", 0.0},
                     {"tolerance", {{"absolute", tolerance}}}});
  metrics.push_back({{"name", "energy of compared cycle 2"},
                     {"kind", "record_cycle_energy"},
                     {"compared_cycle", 2},
                     {"reference", 0.0},
                     {"tolerance", {{"absolute", tolerance}}}});
  for (const char* kind : {"record_excursion_work", "record_excursion_peak_force"})
    metrics.push_back({{"name", kind},
                       {"kind", kind},
                       {"reference", 0.0},
                       {"tolerance", {{"absolute", tolerance}}}});
  metrics.push_back({{"name", "failure"}, {"kind", "record_failure_mode"}, {"expected", true}});
  return metrics;
}

TEST_F(ReferenceTypes, TheModelRunFailsByGlobalBucklingAndCompletes) {
  // The premise of the failure tests: the bare plate buckles as a whole (its flag).
  ASSERT_TRUE(run().result.completed) << run().result.stop_reason;
  const FailureEvent failure = model_failure();
  EXPECT_EQ(failure.mode, FailureMode::global_buckling);
  EXPECT_GE(failure.cycle, 3); // not before the 3 dy cycles
}

TEST_F(ReferenceTypes, SolidRunOfTheSameHistoryGivesZeroErrorForEveryMetric) {
  // Reference (construction): the reference is the model's own hysteresis, in N and mm, at
  // the protocol's own points, so every difference is exactly 0.
  write_solid_run("solid_same");
  const json reference = {{"type", "solid_run"},
                          {"directory", "../solid_same"},
                          {"failure", failure_of(model_failure())}};
  const auto checks = metric_checks(write_specimen("same_solid", reference, every_metric(0.0)));
  ASSERT_EQ(checks.size(), 9u);
  for (const CheckResult& check : checks) {
    EXPECT_EQ(check.status, CheckStatus::pass) << check.name << ": " << check.note;
    ASSERT_TRUE(check.value) << check.name << ": " << check.note;
    if (check.kind != "record_failure_mode") {
      EXPECT_EQ(*check.value, 0.0) << check.name;
    }
  }
  EXPECT_EQ(*checks.back().value, 1.0); // the same failure mode, in the same cycle
}

TEST_F(ReferenceTypes, SolidRunKeepsItsRunTimeForTheReport) {
  // A `brb solid` summary carries solid.run_seconds: the specimen keeps it (the report sets it
  // against the model's run time); a summary without that key leaves it unknown.
  write_solid_run("solid_timed");
  json summary = json::parse(read_file(root() / "solid_timed" / "summary.json"));
  summary["solid"] = {{"run_seconds", 123.5}};
  scratch_->write("solid_timed/summary.json", summary.dump(2));
  const json reference = {{"type", "solid_run"},
                          {"directory", "../solid_timed"},
                          {"failure", failure_of(model_failure())}};
  const Specimen timed = brb::validation::read_specimen(
      write_specimen("timed_solid", reference, every_metric(1.0)), root());
  ASSERT_TRUE(timed.record.has_value());
  ASSERT_TRUE(timed.record->run_seconds.has_value());
  EXPECT_EQ(*timed.record->run_seconds, 123.5);

  write_solid_run("solid_untimed");
  const json untimed_reference = {{"type", "solid_run"},
                                  {"directory", "../solid_untimed"},
                                  {"failure", failure_of(model_failure())}};
  const Specimen untimed = brb::validation::read_specimen(
      write_specimen("untimed_solid", untimed_reference, every_metric(1.0)), root());
  ASSERT_TRUE(untimed.record.has_value());
  EXPECT_FALSE(untimed.record->run_seconds.has_value());
}

TEST_F(ReferenceTypes, ASolidRunsQuasiStaticCheckIsJudgedFromItsSummary) {
  // Issue 6: KE and hourglass energy below 5 % of the internal energy throughout every
  // validation run of the 3D model. The run's summary.json gives its largest ratios; brb
  // validate checks them (automatic checks of the reference): 0.08 fails, 0.01 passes.
  write_solid_run("solid_dynamic");
  json summary = json::parse(read_file(root() / "solid_dynamic" / "summary.json"));
  summary["solid"] = {{"max_kinetic_over_internal", 0.08}, {"max_hourglass_over_internal", 0.01}};
  scratch_->write("solid_dynamic/summary.json", summary.dump(2));
  const json reference = {{"type", "solid_run"},
                          {"directory", "../solid_dynamic"},
                          {"failure", failure_of(model_failure())}};
  const Specimen dynamic = brb::validation::read_specimen(
      write_specimen("dynamic_solid", reference, every_metric(1.0)), root());
  ASSERT_TRUE(dynamic.record.has_value());
  const std::vector<CheckResult> checks = brb::validation::reference_checks(*dynamic.record);
  ASSERT_EQ(checks.size(), 2u);
  EXPECT_EQ(checks[0].kind, "reference_kinetic_ratio");
  EXPECT_EQ(*checks[0].value, 0.08);
  EXPECT_EQ(*checks[0].at_most, brb::validation::kQuasiStaticRatioLimit);
  EXPECT_EQ(checks[0].status, CheckStatus::fail);
  EXPECT_EQ(checks[1].kind, "reference_hourglass_ratio");
  EXPECT_EQ(checks[1].status, CheckStatus::pass);
  // and they are among the specimen's checks, after the run's automatic ones
  const PreparedSpecimen prepared = brb::validation::prepare_specimen(dynamic);
  const RunData data{run().result, run().yield_deformation, run().yield_force,
                     run().yielding_length, &*prepared.record};
  const std::vector<CheckResult> all = brb::validation::evaluate_checks(prepared.specimen, data);
  ASSERT_GT(all.size(), 5u);
  EXPECT_EQ(all[3].kind, "reference_kinetic_ratio");
  EXPECT_EQ(all[4].kind, "reference_hourglass_ratio");

  // a summary without the ratios (or another reference type) adds no check
  write_solid_run("solid_plain");
  const json plain_reference = {{"type", "solid_run"},
                                {"directory", "../solid_plain"},
                                {"failure", failure_of(model_failure())}};
  const Specimen plain = brb::validation::read_specimen(
      write_specimen("plain_solid", plain_reference, every_metric(1.0)), root());
  EXPECT_TRUE(brb::validation::reference_checks(*plain.record).empty());
}

TEST_F(ReferenceTypes, SolverCsvInKilonewtonsAndInchesGivesZeroErrorForEveryMetric) {
  // Reference (construction): the same history written in kN and inches with renamed
  // columns. Converting to kN and inches and back rounds each number by at most an ulp or
  // two (~2e-16 relative), so the errors are zero to 1e-12 (the loop energies, differences
  // of nearly equal areas, amplify round-off the most).
  write_solver_csv("solver_same.csv");
  json reference = solver_reference("solver_same.csv");
  reference["failure"] = failure_of(model_failure());
  const auto checks = metric_checks(write_specimen("same_solver", reference, every_metric(1e-12)));
  ASSERT_EQ(checks.size(), 9u);
  for (const CheckResult& check : checks) {
    EXPECT_EQ(check.status, CheckStatus::pass) << check.name << ": " << check.note;
    ASSERT_TRUE(check.value) << check.name << ": " << check.note;
  }
}

TEST_F(ReferenceTypes, AShiftedForceGivesTheNormalisedRmsErrorOfItsDefinition) {
  // Reference: record_comparison.hpp's definition, sqrt(sum (F - (F + c))^2 / sum (F + c)^2)
  // over the compared points (all protocol points here), computed from the model's forces.
  const double shift = 0.05 * run().yield_force;
  write_solver_csv("solver_shifted.csv", shift);
  double difference = 0.0;
  double reference_square = 0.0;
  for (const brb::analysis::CyclicStep& step : run().result.steps) {
    difference += shift * shift;
    reference_square += (step.force + shift) * (step.force + shift);
  }
  const double expected = std::sqrt(difference / reference_square);
  const json metrics = json::array({{{"name", "nrms"}, {"kind", "record_nrms"}}});
  const auto checks = metric_checks(
      write_specimen("shifted_solver", solver_reference("solver_shifted.csv"), metrics));
  ASSERT_EQ(checks.size(), 1u);
  ASSERT_TRUE(checks[0].value) << checks[0].note;
  EXPECT_NEAR(*checks[0].value, expected, 1e-12 * expected);
  EXPECT_GT(expected, 0.01); // a real difference, not round-off
}

TEST_F(ReferenceTypes, FailureModeAndCycleAreJudgedWithinOneCycle) {
  write_solid_run("solid_failure");
  const FailureEvent model = model_failure();
  const auto status_against = [&](const FailureEvent& stated, const std::string& id) {
    const json reference = {
        {"type", "solid_run"}, {"directory", "../solid_failure"}, {"failure", failure_of(stated)}};
    const json metrics =
        json::array({{{"name", "failure"}, {"kind", "record_failure_mode"}, {"expected", true}}});
    const auto checks = metric_checks(write_specimen(id, reference, metrics));
    EXPECT_EQ(checks.size(), 1u);
    return checks.at(0).status;
  };
  EXPECT_EQ(status_against({model.mode, model.cycle + 1}, "one_cycle_later"), CheckStatus::pass);
  EXPECT_EQ(status_against({model.mode, model.cycle - 1}, "one_cycle_earlier"), CheckStatus::pass);
  EXPECT_EQ(status_against({model.mode, model.cycle + 2}, "two_cycles_later"), CheckStatus::fail);
  EXPECT_EQ(status_against({model.mode, model.cycle - 2}, "two_cycles_earlier"), CheckStatus::fail);
  EXPECT_EQ(status_against({FailureMode::casing_failure, model.cycle}, "other_mode"),
            CheckStatus::fail);
  EXPECT_EQ(status_against({FailureMode::none, 0}, "no_failure"), CheckStatus::fail);
}

TEST_F(ReferenceTypes, AReferenceOnAnotherDeformationPathIsRefused) {
  // Deformations 20 % larger than the protocol's: at 3 dy that is 0.6 dy, beyond the default
  // path tolerance of 0.1 dy. The error names the reference file.
  const fs::path file = write_solver_csv("solver_stretched.csv", 0.0, 1.2);
  const json metrics = json::array({{{"name", "nrms"}, {"kind", "record_nrms"}}});
  const fs::path folder =
      write_specimen("stretched", solver_reference("solver_stretched.csv"), metrics);
  try {
    brb::validation::prepare_specimen(brb::validation::read_specimen(folder, root()));
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(fs::weakly_canonical(error.file()), fs::weakly_canonical(file)) << error.what();
    EXPECT_NE(error.expected().find("does not follow the protocol's deformation path"),
              std::string::npos)
        << error.what();
  }
}

/// A reference spoiled one way, and the JSON path (in metrics.json) or the file (a CSV read
/// while preparing) the error must name.
struct BadReference {
  std::string name;
  std::function<void(json& reference, json& document)> spoil;
  std::string path;         ///< JSON path in metrics.json; empty: an error of the CSV file
  std::string csv_mentions; ///< for a CSV error: what the message must mention
};

/// The bad references need no model run: their CSV is the protocol's points with a force
/// proportional to the deformation (they are refused before any comparison).
class BadReferences : public ReferenceTypes, public ::testing::WithParamInterface<BadReference> {
protected:
  static void SetUpTestSuite() {
    const brb::io::LoadingProtocol protocol = write_brace_and_protocol();
    for (std::size_t k = 0; k < protocol.deformation.size(); ++k) {
      brb::analysis::CyclicStep step;
      step.step = static_cast<int>(k);
      step.cycle = protocol.cycle[k];
      step.deformation = protocol.deformation[k];
      step.force = 1000.0 * protocol.deformation[k];
      run_->result.steps.push_back(step);
    }
  }
};

TEST_P(BadReferences, AreRefusedNamingTheFileAndWhere) {
  const fs::path csv = write_solver_csv("solver_bad.csv");
  json reference = solver_reference("solver_bad.csv");
  json document = {{"metrics", json::array({{{"name", "nrms"}, {"kind", "record_nrms"}}})}};
  GetParam().spoil(reference, document);
  const fs::path folder =
      write_specimen("bad_" + GetParam().name, reference, document["metrics"],
                     document.contains("comparison") ? document["comparison"] : json());
  try {
    brb::validation::prepare_specimen(brb::validation::read_specimen(folder, root()));
    FAIL() << "accepted";
  } catch (const InputError& error) {
    if (GetParam().path.empty()) {
      EXPECT_EQ(fs::weakly_canonical(error.file()), fs::weakly_canonical(csv)) << error.what();
      EXPECT_NE(std::string(error.what()).find(GetParam().csv_mentions), std::string::npos)
          << error.what();
    } else {
      EXPECT_EQ(error.file(), (folder / "metrics.json").string()) << error.what();
      EXPECT_EQ(error.location(), GetParam().path) << error.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Schema, BadReferences,
    ::testing::Values(
        BadReference{"UnknownForceColumn",
                     [](json& r, json&) { r["columns"]["force"] = "RF2 [kN]"; }, "", "RF2 [kN]"},
        BadReference{"UnknownDeformationColumn",
                     [](json& r, json&) { r["columns"]["deformation"] = "U1"; }, "", "U1"},
        BadReference{"UnknownTimeColumn",
                     [](json& r, json&) { r["columns"]["time"] = "Step time"; }, "", "Step time"},
        BadReference{"ForceUnit", [](json& r, json&) { r["units"]["force"] = "lbf"; },
                     "/reference/units/force", ""},
        BadReference{"LengthUnit", [](json& r, json&) { r["units"]["length"] = "ft"; },
                     "/reference/units/length", ""},
        BadReference{"UnitsMissing", [](json& r, json&) { r.erase("units"); }, "/reference/units",
                     ""},
        BadReference{"ExtraColumn", [](json& r, json&) { r["columns"]["strain"] = "E11"; },
                     "/reference/columns/strain", ""},
        BadReference{"UnknownType", [](json& r, json&) { r["type"] = "abaqus"; }, "/reference/type",
                     ""},
        BadReference{"SolidRunWithoutDirectory",
                     [](json& r, json&) {
                       r = {{"type", "solid_run"}, {"directory", "../no_such_run"}};
                     },
                     "/reference/directory", ""},
        BadReference{"SolidRunWithAFile",
                     [](json& r, json&) {
                       r = {{"type", "solid_run"}, {"directory", "."}, {"file", "x.csv"}};
                     },
                     "/reference/file", ""},
        BadReference{"UnknownFailureMode",
                     [](json& r, json&) {
                       r["failure"] = {{"failure_mode", "fracture"}};
                     },
                     "/reference/failure/failure_mode", ""},
        BadReference{"FailureWithoutCycle",
                     [](json& r, json&) {
                       r["failure"] = {{"failure_mode", "core_fracture"}};
                     },
                     "/reference/failure", ""},
        BadReference{"NoFailureWithACycle",
                     [](json& r, json&) {
                       r["failure"] = {{"failure_mode", "none"}, {"cycle", 2}};
                     },
                     "/reference/failure/cycle", ""},
        BadReference{"FailureMetricWithoutFailure",
                     [](json&, json& d) {
                       d["metrics"] = json::array({{{"name", "failure"},
                                                    {"kind", "record_failure_mode"},
                                                    {"expected", true}}});
                     },
                     "/metrics/0", ""},
        BadReference{"RecordRowColumnOfASolverCsv",
                     [](json&, json& d) {
                       d["comparison"] = {{"record_row_column", "row"}};
                     },
                     "/comparison/record_row_column", ""},
        BadReference{"NegativePathTolerance",
                     [](json&, json& d) {
                       d["comparison"] = {{"path_tolerance_dy", -1.0}};
                     },
                     "/comparison/path_tolerance_dy", ""}),
    [](const auto& info) { return info.param.name; });

} // namespace
