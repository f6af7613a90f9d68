// The AISC 341 check examples of validation/aisc/ that run in seconds: the brace whose
// casing is too weak fails by global buckling (its Euler load, 19.5 kN by hand, is below
// Py = 44 kN), and the test stops at the end of the cycle in which it failed.
#include "brb/design/check.hpp"
#include "brb/design/check_input.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace brb::design {
namespace {

const std::filesystem::path kExamples = std::filesystem::path(BRB_SOURCE_DIR) / "validation/aisc";

const Criterion& criterion(const QualificationResult& result, const std::string& id) {
  for (const Criterion& candidate : result.criteria) {
    if (candidate.id == id)
      return candidate;
  }
  throw std::out_of_range("no criterion " + id);
}

TEST(CheckExamples, AWeakCasingFailsByGlobalBuckling) {
  const CheckSpec check = read_check(kExamples / "fails_buckling" / "check.json");
  const CheckResult result = run_check(check);
  EXPECT_FALSE(result.passed());
  EXPECT_FALSE(criterion(result.qualification, "K3.8b instability").passed);
  EXPECT_TRUE(result.qualification.test.indicators.global_buckling);
  EXPECT_FALSE(result.qualification.test.indicators.core_fracture);
  // Stopped at the end of the failing cycle, with the sequence unfinished.
  EXPECT_TRUE(result.qualification.stopped_at_failure);
  EXPECT_FALSE(criterion(result.qualification, "completion").passed);
  EXPECT_LT(result.qualification.cycles.size(), 10U);
  // The casing moved with the core by more than L_y / 250 = 4.8 mm.
  EXPECT_GT(result.qualification.test.indicators.max_casing_lateral_displacement, 1200.0 / 250.0);
}

} // namespace
} // namespace brb::design
