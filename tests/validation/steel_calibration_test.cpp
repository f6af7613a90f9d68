// Steel calibration: the fast axial model against closed-form series-spring responses, the
// Nelder-Mead minimiser on Rosenbrock's function, and the recovery of a force history that
// the fast model itself produced with known parameters.
#include "brb/validation/steel_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace brb::validation {
namespace {

material::SteelParameters perfectly_plastic(double fy) {
  material::SteelParameters steel;
  steel.youngs_modulus = 200000.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = fy;
  return steel;
}

/// Core 1000 mm^2 over 3000 mm, end zones of 10,000 mm^2 over 2 x 500 mm.
AxialBraceIdealisation test_brace() {
  AxialBraceIdealisation brace;
  brace.core_area = 1000.0;
  brace.yielding_length = 3000.0;
  brace.youngs_modulus = 200000.0;
  brace.end_zone_flexibility = 2.0 * 500.0 / (200000.0 * 10000.0);
  return brace;
}

TEST(FastBraceModel, ElasticSeriesStiffnessThenYieldForce) {
  const AxialBraceIdealisation brace = test_brace();
  // Series flexibility: L_y / (E A_c) + f_e = 1.5e-5 + 5e-7 = 1.55e-5 mm/N.
  const double flexibility = 3000.0 / (200000.0 * 1000.0) + brace.end_zone_flexibility;
  const double fy = 250.0; // Py = 250 kN, dy = 250e3 x 1.55e-5 = 3.875 mm
  EXPECT_NEAR(brace.yield_deformation(fy), 250e3 * flexibility, 1e-12);
  const std::vector<double> history{1.0, 3.0, 10.0, 5.0, -10.0};
  const std::vector<double> force = fast_brace_forces(perfectly_plastic(fy), brace, history);
  EXPECT_NEAR(force[0], 1.0 / flexibility, 1e-6);
  EXPECT_NEAR(force[1], 3.0 / flexibility, 1e-6);
  EXPECT_NEAR(force[2], 250e3, 1e-6); // yielded in tension
  // Unloading by 5 mm elastically from +Py: Py - 5 / flexibility.
  EXPECT_NEAR(force[3], 250e3 - 5.0 / flexibility, 1e-6);
  EXPECT_NEAR(force[4], -250e3, 1e-6);
}

TEST(NelderMead, FindsTheMinimumOfRosenbrocksFunction) {
  const auto rosenbrock = [](const std::vector<double>& x) {
    return 100.0 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1.0 - x[0], 2);
  };
  const SimplexMinimum minimum = nelder_mead(rosenbrock, {-1.2, 1.0}, 0.5, 1e-14, 5000, 3);
  EXPECT_NEAR(minimum.point[0], 1.0, 1e-3);
  EXPECT_NEAR(minimum.point[1], 1.0, 2e-3);
  EXPECT_LT(minimum.value, 1e-6);
  EXPECT_LE(minimum.evaluations, 5000 + 10);
}

TEST(SteelCalibration, RecoversAForceHistoryMadeWithKnownParameters) {
  const AxialBraceIdealisation brace = test_brace();
  material::SteelParameters truth = perfectly_plastic(290.0);
  truth.chaboche = {{9000.0, 150.0}, {1200.0, 8.0}};
  truth.voce_saturation = 35.0;
  truth.voce_rate = 6.0;
  // Cycles of 1, 3, 6, 10 dy (dy about 4.5 mm) in steps of about dy / 5.
  std::vector<double> deformation;
  double position = 0.0;
  for (const double amplitude : {4.5, 13.5, 27.0, 45.0}) {
    for (const double target : {amplitude, -amplitude}) {
      const int steps = static_cast<int>(std::ceil(std::abs(target - position) / 0.9));
      for (int i = 1; i <= steps; ++i)
        deformation.push_back(position + (target - position) * i / steps);
      position = target;
    }
  }
  const std::vector<double> test_force = fast_brace_forces(truth, brace, deformation);
  const std::vector<bool> compared(deformation.size(), true);

  material::SteelParameters start = perfectly_plastic(250.0);
  CalibrationOptions options;
  options.side = CalibrationSide::all;
  options.max_evaluations = 4000;
  const CalibrationResult result =
      calibrate_steel(start, brace, deformation, test_force, compared, options);
  EXPECT_GT(result.start_objective, 0.05); // the start is visibly wrong
  EXPECT_LT(result.objective, 0.01);       // the fit reproduces the history within 1 %
  EXPECT_NEAR(result.steel.yield_stress, 290.0, 0.1 * 290.0);
  EXPECT_EQ(result.steel.chaboche.size(), 2u);
  EXPECT_LE(result.evaluations, 4000 + 10);
}

} // namespace
} // namespace brb::validation
