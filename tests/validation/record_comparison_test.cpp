// Record comparison metrics against hand-computed references: elastic-perfectly-plastic
// parallelogram loops (area 4 Fy (A - Fy / K)), scaled forces (known relative errors) and
// asymmetric loops (known beta).
#include "brb/validation/record_comparison.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace brb::validation {
namespace {

/// Deformation and force of an elastic-perfectly-plastic spring (stiffness K, strength Fy,
/// compression strength Fc) taken 0 -> +A -> (-A -> +A) x loops -> 0, with a point at every
/// corner of the loops so that the trapezoidal rule is exact (the force is piecewise linear
/// in the deformation).
struct Loops {
  std::vector<double> deformation;
  std::vector<double> force;
  void add(double d, double f) {
    deformation.push_back(d);
    force.push_back(f);
  }
};

Loops parallelogram_loops(double stiffness, double fy, double fc, double amplitude, int loops) {
  Loops path;
  path.add(0.0, 0.0);
  path.add(fy / stiffness, fy); // yield
  path.add(amplitude, fy);      // first maximum
  for (int loop = 0; loop < loops; ++loop) {
    path.add(amplitude - (fy + fc) / stiffness, -fc); // unloaded and yielded in compression
    path.add(-amplitude, -fc);                        // minimum
    path.add(-amplitude + (fy + fc) / stiffness, fy); // reloaded to tension yield
    path.add(amplitude, fy);                          // maximum
  }
  path.add(amplitude - fy / stiffness, 0.0); // unloaded to zero force
  return path;
}

TEST(RecordComparison, NormalisedRmsErrorOfAScaledForceIsTheScale) {
  const std::vector<double> test{1.0, -2.0, 3.0, -4.0};
  std::vector<double> model;
  for (const double f : test)
    model.push_back(1.1 * f);
  EXPECT_NEAR(normalised_rms_force_error(model, test), 0.1, 1e-12);
  // Hand computed: differences (1, 0), test (3, 4): sqrt(1 / 25) = 0.2.
  EXPECT_NEAR(
      normalised_rms_force_error(std::vector<double>{4.0, 4.0}, std::vector<double>{3.0, 4.0}), 0.2,
      1e-12);
  EXPECT_THROW(normalised_rms_force_error(std::vector<double>{1.0}, std::vector<double>{0.0}),
               std::invalid_argument);
}

TEST(RecordComparison, CyclesRunFromMaximumToMaximumAndEncloseTheParallelogramArea) {
  const double stiffness = 100.0, fy = 10.0, amplitude = 1.0;
  const Loops path = parallelogram_loops(stiffness, fy, fy, amplitude, 3);
  const std::vector<CycleSpan> cycles = segment_cycles(path.deformation, 0.05);
  // Maxima at points 2, 6, 10, 14: three closed cycles.
  ASSERT_EQ(cycles.size(), 3u);
  EXPECT_EQ(cycles[0].first, 2u);
  EXPECT_EQ(cycles[0].last, 6u);
  EXPECT_EQ(cycles[2].last, 14u);
  const double area = 4.0 * fy * (amplitude - fy / stiffness); // 36 N mm
  for (const CycleSpan& cycle : cycles) {
    EXPECT_NEAR(loop_energy(path.deformation, path.force, cycle), area, 1e-12);
    EXPECT_NEAR(compression_tension_ratio(path.force, cycle), 1.0, 1e-15);
  }
}

TEST(RecordComparison, EnergyErrorAndBetaOfKnownLoops) {
  const double stiffness = 100.0, fy = 10.0, amplitude = 1.0;
  // Test: compression strength 1.2 Fy (beta 1.2).
  const Loops test = parallelogram_loops(stiffness, fy, 1.2 * fy, amplitude, 2);
  // The model force, at the same deformation points, is the test force scaled by 0.9.
  std::vector<double> scaled_force;
  for (const double f : test.force)
    scaled_force.push_back(0.9 * f);
  const RecordComparison comparison =
      compare_with_record(test.deformation, test.force, scaled_force, {0.05, 0.05});
  ASSERT_EQ(comparison.cycles.size(), 2u);
  EXPECT_EQ(comparison.scored_cycles, 2u);
  // Area of the asymmetric parallelogram: (Fy + Fc) (2 A - (Fy + Fc) / K).
  const double area = (fy + 1.2 * fy) * (2 * amplitude - (2.2 * fy) / stiffness);
  EXPECT_NEAR(comparison.cycles[0].test_energy, area, 1e-12);
  EXPECT_NEAR(comparison.cycles[0].model_energy, 0.9 * area, 1e-12);
  EXPECT_NEAR(comparison.max_cycle_energy_error, 0.1, 1e-12);
  EXPECT_NEAR(comparison.cycles[1].test_beta, 1.2, 1e-12);
  EXPECT_NEAR(comparison.max_beta_difference, 0.0, 1e-12); // scaling keeps beta
  EXPECT_NEAR(comparison.normalised_rms_error, 0.1, 1e-12);

  // A symmetric model loop with the same corners in deformation: beta 1 against 1.2.
  std::vector<double> symmetric_force = test.force;
  for (double& f : symmetric_force)
    f = f < 0.0 ? f / 1.2 : f;
  const RecordComparison symmetric =
      compare_with_record(test.deformation, test.force, symmetric_force, {0.05, 0.05});
  EXPECT_NEAR(symmetric.max_beta_difference, 0.2, 1e-12);
  // AISC 341's factors from the test (F4.2a: the largest over the cycles): beta 1.2 both for
  // the test and the scaled model, 1 for the symmetric one; Tmax Fy and 0.9 Fy
  EXPECT_NEAR(comparison.largest_test_beta, 1.2, 1e-12);
  EXPECT_NEAR(comparison.largest_model_beta, 1.2, 1e-12);
  EXPECT_NEAR(symmetric.largest_model_beta, 1.0, 1e-12);
  EXPECT_NEAR(comparison.largest_test_tension, fy, 1e-12);
  EXPECT_NEAR(comparison.largest_model_tension, 0.9 * fy, 1e-12);
}

TEST(RecordComparison, NearlyElasticCyclesBelowTheEnergyFloorAreNotScored) {
  const double stiffness = 100.0, fy = 10.0;
  // One plastic cycle of amplitude 1, then an elastic cycle of amplitude 0.05 (zero area)
  // about the residual state, then back to the plastic maximum.
  Loops path = parallelogram_loops(stiffness, fy, fy, 1.0, 1);
  path.deformation.resize(7);
  path.force.resize(7);                         // ends at the second maximum (1, Fy)
  const double residual = 1.0 - fy / stiffness; // zero force
  path.add(residual, 0.0);
  path.add(residual - 0.05, -5.0);
  path.add(residual, 0.0);
  path.add(1.0, fy);
  path.add(residual, 0.0);
  const RecordComparison comparison =
      compare_with_record(path.deformation, path.force, path.force, {0.01, 0.05});
  ASSERT_EQ(comparison.cycles.size(), 2u);
  EXPECT_TRUE(comparison.cycles[0].scored);
  EXPECT_FALSE(comparison.cycles[1].scored); // area 0 against 36
  EXPECT_NEAR(comparison.cycles[1].test_energy, 0.0, 1e-12);
  EXPECT_EQ(comparison.scored_cycles, 1u);
  EXPECT_EQ(comparison.max_cycle_energy_error, 0.0);
}

TEST(RecordComparison, BetaIsComparedOnlyWhereTheTestHasATensionPeak) {
  // A record that, after a full cycle (+1 / -1 mm, 10 N / -12 N), cycles about -0.75 mm in
  // compression (a hold point's wiggle). Segmented from maximum to maximum (the last point
  // makes -0.5 mm a maximum), its third cycle runs -0.5 -> -1 -> -0.5 mm with the force
  // between -2 and -12 N: it has loop energy (hand computed, trapezoidal: 0.7 + 4.8 - 0.7 -
  // 0.8 = 4.0 N mm, above 5 % of the first cycle's) but no tension peak, and beta = Pmax /
  // Tmax is undefined for it.
  const std::vector<double> deformation{0.0,  0.1,  1.0,  0.78, -1.0, -0.78, 1.0,  0.78,
                                        -1.0, -0.9, -0.5, -0.6, -1.0, -0.9,  -0.5, -0.6};
  const std::vector<double> test_force{0.0,   10.0, 10.0, -12.0, -12.0, 10.0, 10.0, -12.0,
                                       -12.0, -2.0, -2.0, -12.0, -12.0, -2.0, -2.0, -12.0};
  std::vector<double> scaled_force;
  for (const double f : test_force)
    scaled_force.push_back(0.9 * f);
  const RecordComparison comparison =
      compare_with_record(deformation, test_force, scaled_force, {0.05, 0.05});
  ASSERT_EQ(comparison.cycles.size(), 3u);
  EXPECT_EQ(comparison.scored_cycles, 3u);
  EXPECT_NEAR(comparison.cycles[2].test_energy, 4.0, 1e-12);
  EXPECT_TRUE(comparison.cycles[0].beta_compared);
  EXPECT_TRUE(comparison.cycles[1].beta_compared);
  EXPECT_FALSE(comparison.cycles[2].beta_compared);
  EXPECT_EQ(comparison.beta_cycles, 2u);
  // scaling keeps beta: no difference on the two compared cycles (the third was infinite)
  EXPECT_NEAR(comparison.max_beta_difference, 0.0, 1e-12);
  EXPECT_NEAR(comparison.max_cycle_energy_error, 0.1, 1e-12); // energy is still scored

  // With a beta force floor (the specimens pass Py) a cycle's beta is compared only where
  // both test peaks reach it: 10 N tension and 12 N compression reach 10 N, not 10.5 N.
  RecordComparisonOptions at_yield{0.05, 0.05, 10.0};
  EXPECT_EQ(compare_with_record(deformation, test_force, scaled_force, at_yield).beta_cycles, 2u);
  at_yield.beta_force_floor = 10.5;
  const RecordComparison above =
      compare_with_record(deformation, test_force, scaled_force, at_yield);
  EXPECT_EQ(above.beta_cycles, 0u);
  EXPECT_EQ(above.scored_cycles, 3u);
  EXPECT_EQ(above.largest_test_beta, 0.0); // AISC's beta only from yield-level cycles

  // A model without tension in a cycle where the test has some is the worst difference.
  std::vector<double> no_tension = scaled_force;
  for (std::size_t i = 2; i <= 6; ++i)
    no_tension[i] = std::min(no_tension[i], -1.0);
  const RecordComparison without =
      compare_with_record(deformation, test_force, no_tension, {0.05, 0.05});
  EXPECT_TRUE(std::isinf(without.max_beta_difference));
}

TEST(RecordComparison, ExcursionsOfAHalfCycleProtocolAreScoredWithoutAClosedCycle) {
  // The source's small-BRB case 1: shortening to -A, then elongating to +B, which closes no
  // cycle. Elastic-perfectly-plastic spring (K, Fy); corners as points, so the trapezoidal
  // rule is exact. Hand computed:
  //  - excursion 1 (0 -> -A): work Fy (A - Fy / K) + Fy^2 / (2 K) = Fy (A - Fy / (2 K)),
  //    peak compression Fy;
  //  - excursion 2 (-A -> +B): unloading -Fy^2 / (2 K), reloading +Fy^2 / (2 K), then
  //    plastic Fy (B - (-A + 2 Fy / K)): work Fy (A + B - 2 Fy / K), peak tension Fy.
  const double stiffness = 100.0, fy = 10.0, a = 1.0, b = 0.5;
  Loops path;
  path.add(0.0, 0.0);
  path.add(-fy / stiffness, -fy);
  path.add(-a, -fy);
  path.add(-a + fy / stiffness, 0.0);
  path.add(-a + 2 * fy / stiffness, fy);
  path.add(b, fy);
  EXPECT_TRUE(segment_cycles(path.deformation, 0.05).empty());
  const std::vector<CycleSpan> excursions = segment_excursions(path.deformation, 0.05);
  ASSERT_EQ(excursions.size(), 2u);
  EXPECT_EQ(excursions[0].first, 0u);
  EXPECT_EQ(excursions[0].last, 2u);
  EXPECT_EQ(excursions[1].first, 2u);
  EXPECT_EQ(excursions[1].last, 5u);
  EXPECT_NEAR(loop_energy(path.deformation, path.force, excursions[0]),
              fy * (a - fy / (2 * stiffness)), 1e-12);
  EXPECT_NEAR(loop_energy(path.deformation, path.force, excursions[1]),
              fy * (a + b - 2 * fy / stiffness), 1e-12);
  EXPECT_EQ(excursion_peak(path.deformation, path.force, excursions[0]), fy); // compression
  EXPECT_EQ(excursion_peak(path.deformation, path.force, excursions[1]), fy); // tension

  // A model 10 % stronger in compression only: excursion 1's work and peak are 10 % off;
  // excursion 2's peak (tension) is not, its work changes by the unloading branch's part.
  std::vector<double> model = path.force;
  for (double& f : model)
    f = f < 0.0 ? 1.1 * f : f;
  const RecordComparison comparison =
      compare_with_record(path.deformation, path.force, model, {0.05, 0.05});
  EXPECT_EQ(comparison.scored_cycles, 0u);
  ASSERT_EQ(comparison.excursions.size(), 2u);
  EXPECT_EQ(comparison.scored_excursions, 2u);
  EXPECT_NEAR(comparison.excursions[0].work_error(), 0.1, 1e-12);
  EXPECT_NEAR(comparison.excursions[0].peak_error(), 0.1, 1e-12);
  EXPECT_NEAR(comparison.excursions[1].peak_error(), 0.0, 1e-12);
  // excursion 2 of the model: the unloading half-triangle from -1.1 Fy to 0 spans the same
  // deformation, so its area is 1.1 x -Fy^2 / (2 K)
  const double test_work = fy * (a + b - 2 * fy / stiffness);
  const double model_work = test_work - 0.1 * fy * fy / (2 * stiffness);
  EXPECT_NEAR(comparison.excursions[1].model_work, model_work, 1e-12);
  EXPECT_NEAR(comparison.max_excursion_work_error, 0.1, 1e-12);
  EXPECT_NEAR(comparison.max_excursion_peak_error, 0.1, 1e-12);
}

TEST(RecordComparison, AMonotonicHistoryIsOneExcursion) {
  // 0 -> A in tension (the source's case 2): one excursion from the first to the last point.
  const std::vector<double> deformation{0.0, 0.1, 0.5, 1.0};
  const std::vector<double> force{0.0, 10.0, 10.0, 10.0};
  const std::vector<CycleSpan> excursions = segment_excursions(deformation, 0.05);
  ASSERT_EQ(excursions.size(), 1u);
  EXPECT_EQ(excursions[0].first, 0u);
  EXPECT_EQ(excursions[0].last, 3u);
  EXPECT_TRUE(segment_excursions(std::vector<double>{0.0}, 0.05).empty());
}

} // namespace
} // namespace brb::validation
