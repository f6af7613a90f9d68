// The `auto` fidelity stays within its stated error bound (model::kAutoErrorBound, derived in
// bench/PARETO.md from girona_D3, brbf3 and brbf9) on a case NOT used to derive it: Girona bar
// D1 (bench/pareto/d1.json, "auto_rule": "check"), a smaller core in a smaller tube, against
// the finest full setting of that matrix (8 core elements), on every metric of the study.
#include "brb/model/brace_fidelity.hpp"
#include "brb/study/pareto_matrix.hpp"
#include "brb/study/pareto_runner.hpp"

#include <gtest/gtest.h>

namespace {

using namespace brb::study;

TEST(ParetoAuto, StaysWithinItsBoundOnACaseNotUsedToDeriveIt) {
  ParetoCase study_case = read_pareto_matrix(BRB_SOURCE_DIR "/bench/pareto/d1.json");
  ASSERT_EQ(study_case.auto_rule, AutoRuleRole::check);
  // Only `auto` and the reference: the other settings do not enter the check.
  const ParetoSetting reference = study_case.settings.at(study_case.reference);
  ParetoSetting automatic;
  for (const ParetoSetting& setting : study_case.settings) {
    if (setting.fidelity == SettingFidelity::automatic)
      automatic = setting;
  }
  ASSERT_EQ(automatic.fidelity, SettingFidelity::automatic);
  study_case.settings = {reference, automatic};
  study_case.reference = 0;
  ParetoRunOptions options;
  options.repeats = 1;
  const CaseOutcome outcome = run_pareto_case(study_case, options);
  const SettingOutcome& ref = outcome.settings[0];
  const SettingOutcome& got = outcome.settings[1];
  ASSERT_TRUE(ref.ran && ref.stop_reason.empty()) << ref.failure << ref.stop_reason;
  ASSERT_TRUE(got.ran && got.stop_reason.empty()) << got.failure << got.stop_reason;
  EXPECT_EQ(got.built_as, "truss"); // tube, Euler margin and friction as the rule asks
  EXPECT_LE(*got.errors.cycle_energy, brb::model::kAutoErrorBound);
  EXPECT_LE(*got.errors.peak_force, brb::model::kAutoErrorBound);
  EXPECT_LE(*got.errors.beta, brb::model::kAutoErrorBound);
}

} // namespace
