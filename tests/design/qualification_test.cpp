// The virtual qualification test's loop and tables on an elastic-perfectly plastic brace
// (the truss fidelity with a non-hardening core, fast), against an independent
// elastic-perfectly plastic computation over the same deformation points.
#include "brb/design/qualification.hpp"

#include "support/brace_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace brb::design {
namespace {

/// The Girona D3 core with its end zones, as the truss fidelity, without hardening: an
/// elastic-perfectly plastic brace of yield deformation dy (end zones included).
model::BraceModel perfectly_plastic_truss() {
  model::BraceSpec spec = test::girona_d3_bare_core(4, true);
  spec.steel.kinematic_hardening = 0.0;
  spec.steel.isotropic_hardening = 0.0;
  return model::build_brace_truss_model(spec);
}

/// Cumulative inelastic deformation (multiples of dy) at the end of each cycle of an
/// elastic-perfectly plastic spring (K0 = Py / dy) driven through the test's own points:
/// F_k = clamp(F_(k-1) + K0 (d_k - d_(k-1)), -Py, Py), CID += |dd - dF / K0| / dy.
std::vector<double> perfectly_plastic_cid(const analysis::CyclicTestResult& test, double py,
                                          double dy) {
  const double k0 = py / dy;
  double force = 0.0;
  double cid = 0.0;
  std::vector<double> at_cycle_end;
  for (std::size_t k = 1; k < test.steps.size(); ++k) {
    const double dd = test.steps[k].deformation - test.steps[k - 1].deformation;
    const double next = std::clamp(force + k0 * dd, -py, py);
    cid += std::abs(dd - (next - force) / k0) / dy;
    force = next;
    const bool ends = k + 1 == test.steps.size() || test.steps[k + 1].cycle != test.steps[k].cycle;
    if (ends)
      at_cycle_end.push_back(cid);
  }
  return at_cycle_end;
}

TEST(Qualification, AddsCyclesAtOneAndAHalfDbmUntilTheBracesOwnCidReaches200) {
  model::BraceModel brace = perfectly_plastic_truss();
  const double dy = brace.yield_deformation;
  QualificationInput input;
  input.design_deformation = 3.0 * dy;
  input.tested_yield_force = brace.yield_force;
  input.edition = edition_parameters(Edition::aisc341_16);
  input.beta_limit = input.edition.beta_limit;
  input.max_step = 0.1 * dy;
  const QualificationResult result = run_qualification(brace, input);
  ASSERT_TRUE(result.test.completed) << result.test.stop_reason;

  const std::vector<double> reference = perfectly_plastic_cid(result.test, brace.yield_force, dy);
  ASSERT_EQ(reference.size(), result.cycles.size());
  for (std::size_t c = 0; c < reference.size(); ++c) {
    EXPECT_NEAR(result.cycles[c].cumulative_inelastic_deformation, reference[c], 1e-6) << c;
  }
  // The extra cycles stop at the first one that reaches 200 dy: the cycle before it is short.
  const std::size_t cycles = result.cycles.size();
  ASSERT_EQ(cycles, 10U + static_cast<std::size_t>(result.extra_cycles));
  EXPECT_GE(reference.back(), 200.0);
  EXPECT_LT(reference[cycles - 2], 200.0);
  EXPECT_TRUE(result.cumulative_target_reached);
  // The model's own count against the hand estimate (88 + 14 per cycle: 8 cycles): the
  // first cycle at 1.5 dy starts from the virgin state and yields 1.5 dy, not the 2 dy of a
  // stabilised loop, so steps 1-5 give 87 (the reference above; a hand count of the same
  // elastic-perfectly plastic path gives 0, 0, 1.5, 3.5, 11, 19, 33, 47, 67, 87), 8 cycles
  // at 4.5 dy reach 199 and a ninth is needed.
  EXPECT_EQ(result.estimated_extra_cycles, 8);
  EXPECT_EQ(result.extra_cycles, 9);

  // Per-cycle table: amplitudes of K3.4c, steps, beta = omega = 1 for a symmetric
  // non-hardening core (Tmax = Pmax = Py beyond dy).
  const std::vector<double> steps{1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6};
  for (std::size_t c = 0; c < cycles; ++c) {
    const QualificationCycle& cycle = result.cycles[c];
    EXPECT_EQ(cycle.sequence_step, static_cast<int>(steps[std::min<std::size_t>(c, 10)]));
    if (cycle.beyond_yield) {
      EXPECT_NEAR(cycle.beta, 1.0, 1e-9) << c;
      EXPECT_NEAR(cycle.omega, 1.0, 1e-9) << c;
    }
    EXPECT_LE(cycle.largest_force_drop, 1e-9) << c; // perfectly plastic: never softens
  }
  EXPECT_FALSE(result.cycles[1].beyond_yield); // step 1 at dy
  EXPECT_TRUE(result.cycles[2].beyond_yield);  // 0.5 Delta_bm = 1.5 dy
  EXPECT_TRUE(result.cycles[9].in_adjustment_range);
  EXPECT_NEAR(result.beta, 1.0, 1e-9);
  EXPECT_NEAR(result.omega, 1.0, 1e-9);
  // The truss's core strain at 2 Delta_bm: the core's part of 6 dy.
  ASSERT_TRUE(result.core_strain_at_2dbm.has_value());
  EXPECT_GT(std::abs(*result.core_strain_at_2dbm), 0.0);
}

TEST(Qualification, AHardeningCoreFailsTheBetaLimitWhenItIsSetBelowItsRatio) {
  // Same brace, bilinear kinematic hardening H = 21000 MPa: symmetric, so Pmax / Tmax = 1 in
  // stabilised cycles; a limit below 1 cannot be met and the verdict says why.
  model::BraceSpec spec = test::girona_d3_bare_core(4, true);
  model::BraceModel brace = model::build_brace_truss_model(spec);
  const double dy = brace.yield_deformation;
  QualificationInput input;
  input.design_deformation = 4.0 * dy;
  input.tested_yield_force = brace.yield_force;
  input.edition = edition_parameters(Edition::aisc341_16);
  input.beta_limit = 0.9;
  input.max_step = 0.2 * dy;
  const QualificationResult result = run_qualification(brace, input);
  ASSERT_TRUE(result.test.completed);
  EXPECT_FALSE(result.passed);
  EXPECT_EQ(failed_criteria(result), "K3.8d beta");
  // Hardening: Tmax above Py in every cycle beyond dy, omega > 1.
  EXPECT_GT(result.omega, 1.0);
  for (const Criterion& criterion : result.criteria) {
    if (criterion.id == "K3.8c tension") {
      EXPECT_TRUE(criterion.passed);
      EXPECT_GT(criterion.value, 1.0);
    }
  }
}

} // namespace
} // namespace brb::design
