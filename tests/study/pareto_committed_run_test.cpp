// A frame setting of `brb bench pareto` read from a committed `brb frame` run (committed_run):
// the study takes the run's drifts, brace CIDs and recorded wall time instead of running it,
// measures the other settings against it, and refuses a run of another case or setting.
#include "brb/io/input_error.hpp"
#include "brb/study/pareto_matrix.hpp"
#include "brb/study/pareto_runner.hpp"
#include "io/scratch_directory.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace {

using namespace brb::study;
using brb::testing::ScratchDirectory;
using nlohmann::json;

const std::string kModel = BRB_SOURCE_DIR "/frames/brbf3/model.json";
const std::string kMotion = BRB_SHARED_DIR "/data/ground_motions/elCentro.AT2";
constexpr double kWindow = 0.3; // s: the braces stay elastic; a truss run takes milliseconds
constexpr double kStep = 0.01;  // s

json frame_matrix(const std::string& summary) {
  return {{"name", "brbf3"},
          {"kind", "frame"},
          {"model", kModel},
          {"motion", kMotion},
          {"duration", kWindow},
          {"settings",
           {{{"label", "truss"}, {"fidelity", "truss"}, {"dt", kStep}},
            {{"label", "full-16"},
             {"fidelity", "full"},
             {"core_elements", 16},
             {"dt", kStep},
             {"committed_run", summary}}}}};
}

/// A summary.json as `brb frame` writes it (the fields the study reads), for the matrix's
/// model, record, window and step with every brace `fidelity`: the drifts and CIDs given.
json committed_summary(const json& max_drift, const json& residual_drift, const json& cids,
                       const std::string& fidelity = "full") {
  json braces = json::array();
  for (const auto& cid : cids)
    braces.push_back({{"id", 1}, {"fidelity", fidelity}, {"cid", cid}});
  return {{"model", "frames/brbf3/model.json"},
          {"motion", "../shared/data/ground_motions/elCentro.AT2"},
          {"scale", 1.0},
          {"dt", kStep},
          {"duration", kWindow},
          {"end_time", kWindow},
          {"converged", true},
          {"collapse", false},
          {"stop_reason", "completed"},
          {"max_drift", max_drift},
          {"residual_drift", residual_drift},
          {"braces", braces},
          {"wall_time", 1234.5},
          {"core_elements", nullptr}}; // the brace files' (brbf3's: 16)
}

TEST(ParetoCommittedRun, ItsDriftsAndTimeAreReadAndTheOtherSettingsMeasuredAgainstThem) {
  const ScratchDirectory scratch;
  // First the truss alone (as its own reference): its drifts and CIDs are what the committed
  // reference is made from.
  // Reference drifts 10 % larger than the truss's in every story: the truss's peak-drift error
  // is then |d - 1.1 d| / (1.1 d) = 1 / 11 exactly; CIDs equal: error 0.
  const auto truss_only = [&]() {
    json matrix = frame_matrix("unused");
    matrix["settings"] = {{{"label", "truss"}, {"fidelity", "truss"}, {"dt", kStep}},
                          {{"label", "full-1"}, {"fidelity", "full"}, {"dt", kStep}}};
    matrix["reference"] = "full-1";
    ParetoCase study_case = read_pareto_matrix(scratch.write("probe.json", matrix.dump()));
    study_case.settings.resize(1); // the truss only: as its own (unused) reference
    study_case.reference = 0;
    return run_pareto_case(study_case, {}).settings.front();
  };
  const SettingOutcome truss = truss_only();
  ASSERT_TRUE(truss.ran && truss.frame.completed);
  ASSERT_GT(truss.frame.max_drift.size(), 1u);
  json drifts = json::array(), residuals = json::array(), cids = json::array();
  for (const double drift : truss.frame.max_drift)
    drifts.push_back(1.1 * drift);
  for (const double residual : truss.frame.residual_drift)
    residuals.push_back(residual);
  for (const double cid : truss.frame.cid)
    cids.push_back(cid);
  const auto summary =
      scratch.write("full16_summary.json", committed_summary(drifts, residuals, cids).dump());

  const ParetoCase study_case =
      read_pareto_matrix(scratch.write("m.json", frame_matrix(summary.string()).dump()));
  ASSERT_EQ(study_case.settings[study_case.reference].label, "full-16");
  const CaseOutcome outcome = run_pareto_case(study_case, {});
  const SettingOutcome& reference = outcome.settings[1];
  EXPECT_TRUE(reference.committed);
  EXPECT_TRUE(reference.ran);
  EXPECT_EQ(reference.median_time, 1234.5); // the time the run recorded
  EXPECT_EQ(reference.built_as, "0 truss; " + std::to_string(cids.size()) + " full");
  ASSERT_TRUE(reference.errors.peak_drift.has_value());
  EXPECT_EQ(*reference.errors.peak_drift, 0.0);

  const SettingOutcome& measured = outcome.settings[0];
  EXPECT_FALSE(measured.committed);
  ASSERT_TRUE(measured.errors.peak_drift.has_value());
  EXPECT_NEAR(*measured.errors.peak_drift, 1.0 / 11.0, 1e-12);
  ASSERT_TRUE(measured.errors.cid.has_value());
  EXPECT_EQ(*measured.errors.cid, 0.0);
  ASSERT_TRUE(measured.errors.residual_drift.has_value());
  EXPECT_EQ(*measured.errors.residual_drift, 0.0);
}

TEST(ParetoCommittedRun, WithRunCommittedTheSettingIsRunInstead) {
  const ScratchDirectory scratch;
  // A committed "run" that is a truss setting's, with drifts no analysis gives (all 1.0): run
  // anyway, the setting's drifts are the analysis's, and it is not marked committed.
  const json ones = json::array({1.0, 1.0, 1.0});
  json matrix = frame_matrix("");
  matrix["settings"] = {{{"label", "truss"}, {"fidelity", "truss"}, {"dt", kStep}},
                        {{"label", "full-1"}, {"fidelity", "full"}, {"dt", kStep}}};
  matrix["settings"][0]["committed_run"] =
      scratch.write("t.json", committed_summary(ones, ones, json::array({0, 0}), "truss").dump())
          .string();
  matrix["reference"] = "full-1";
  ParetoCase study_case = read_pareto_matrix(scratch.write("m.json", matrix.dump()));
  study_case.settings.resize(1);
  study_case.reference = 0;
  ParetoRunOptions options;
  options.run_committed = true;
  const SettingOutcome run = run_pareto_case(study_case, options).settings.front();
  EXPECT_FALSE(run.committed);
  ASSERT_TRUE(run.ran);
  ASSERT_FALSE(run.frame.max_drift.empty());
  EXPECT_LT(run.frame.max_drift.front(), 0.01); // a real drift ratio of an elastic window
  const SettingOutcome read = run_pareto_case(study_case, {}).settings.front();
  EXPECT_TRUE(read.committed);
  EXPECT_EQ(read.frame.max_drift.front(), 1.0);
}

/// The error of reading `summary` as the committed full-16 run of frame_matrix, whose brace
/// files have `file_elements` core elements, or "".
std::string committed_error(const json& summary, std::optional<int> file_elements = 16) {
  const ScratchDirectory scratch;
  const auto file = scratch.write("s.json", summary.dump());
  try {
    const ParetoCase study_case =
        read_pareto_matrix(scratch.write("m.json", frame_matrix(file.string()).dump()));
    // brbf3 has no free vibration: the analysed time is the window
    (void)read_committed_frame_run(file, study_case, study_case.settings[1],
                                   {kStep, kWindow, file_elements});
  } catch (const brb::io::InputError& error) {
    EXPECT_EQ(error.file(), file.string());
    return error.what();
  }
  return "";
}

TEST(ParetoCommittedRun, ARunOfAnotherCaseOrSettingIsRefusedNamingTheField) {
  const json two = json::array({0.01, 0.02});
  const json good = committed_summary(two, two, json::array({1.0}));
  EXPECT_EQ(committed_error(good), "");

  json other = good;
  other["dt"] = 0.005;
  EXPECT_NE(committed_error(other).find(
                "/dt: the committed run of setting \"full-16\" must be at the setting's step"),
            std::string::npos)
      << committed_error(other);
  other = good;
  other["duration"] = 2.5;
  EXPECT_NE(committed_error(other).find("/duration: the committed run of setting \"full-16\" must "
                                        "be over the matrix's window and the model's free "
                                        "vibration, 0.3 s (brb frame --duration 0.3)"),
            std::string::npos);
  other = good;
  other["model"] = "frames/brbf9/model.json";
  EXPECT_NE(committed_error(other).find("/model: the committed run of setting \"full-16\" must be "
                                        "of the matrix's model, brbf3/model.json"),
            std::string::npos);
  other = good;
  other["motion"] = "Rinaldi228.AT2";
  EXPECT_NE(committed_error(other).find("/motion: "), std::string::npos);
  other = good;
  other["scale"] = 2.0;
  EXPECT_NE(committed_error(other).find("/scale: "), std::string::npos);
  other = good;
  other["braces"][0]["fidelity"] = "truss";
  EXPECT_NE(committed_error(other).find("/braces/0/fidelity: the committed run of setting "
                                        "\"full-16\" must be with every brace full"),
            std::string::npos);
  other = good;
  other["core_elements"] = 4; // brb frame --core-elements 4: not the setting's 16
  EXPECT_NE(committed_error(other).find("/core_elements: the committed run of setting "
                                        "\"full-16\" must be with every brace of the setting's "
                                        "core element count, 16"),
            std::string::npos)
      << committed_error(other);
  other["core_elements"] = 16; // said explicitly: right, whatever the files say
  EXPECT_EQ(committed_error(other, 8), "");
  // null: the files' count, which must then be the setting's
  EXPECT_NE(committed_error(good, 8).find("/core_elements: "), std::string::npos);
  EXPECT_NE(committed_error(good, std::nullopt).find("not all the same"), std::string::npos);
  other = good;
  other.erase("core_elements"); // a run written before the field: the files' count
  EXPECT_EQ(committed_error(other), "");
  EXPECT_NE(committed_error(other, 8).find("it gives no core_elements"), std::string::npos);
  other = good;
  other.erase("wall_time");
  EXPECT_NE(committed_error(other).find("/wall_time: "), std::string::npos);
}

TEST(ParetoCommittedRun, OnlyFrameSettingsNameOneAndQuickRunsThem) {
  const ScratchDirectory scratch;
  const auto summary = scratch.write("s.json", "{}");
  json matrix = {
      {"name", "plate"},
      {"kind", "component"},
      {"brace", BRB_SOURCE_DIR "/examples/braces/plate_core_bare.json"},
      {"protocol", BRB_SOURCE_DIR "/examples/protocols/increasing_dy.json"},
      {"settings", {{{"label", "full"}, {"fidelity", "full"}, {"committed_run", summary}}}}};
  try {
    (void)read_pareto_matrix(scratch.write("c.json", matrix.dump()));
    FAIL() << "a component setting with a committed run was accepted";
  } catch (const brb::io::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/settings/0/committed_run: committed_run"),
              std::string::npos)
        << error.what();
  }
  json missing = frame_matrix((scratch.path() / "none.json").string());
  try {
    (void)read_pareto_matrix(scratch.write("f.json", missing.dump()));
    FAIL() << "a missing committed run was accepted";
  } catch (const brb::io::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/settings/1/committed_run: "), std::string::npos);
  }
  const ParetoCase frame_case =
      read_pareto_matrix(scratch.write("g.json", frame_matrix(summary.string()).dump()));
  EXPECT_TRUE(frame_case.settings[1].committed_run.has_value());
  EXPECT_FALSE(frame_case.quick().settings[1].committed_run.has_value());
}

} // namespace
