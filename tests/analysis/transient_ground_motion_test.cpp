// A damped linear oscillator under a short ground-acceleration record (a half-sine pulse
// sampled at 0.01 s, then zeros), against the exact response to the piecewise-linear record
// (the input GroundAcceleration::at defines), computed here segment by segment in closed form
// (the Nigam-Jennings idea: exact integration of a linear load over each sample interval;
// Chopra, Dynamics of Structures, sec. 5.2). Newmark average acceleration is second-order
// accurate, so the error must fall by 4 when the step is halved.
#include "brb/analysis/transient_analysis.hpp"
#include "brb/element/corot_truss.hpp"
#include "brb/material/steel_uniaxial.hpp"
#include "brb/model/dof_map.hpp"
#include "support/oscillator_models.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::analysis {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kMass = 1.5;   // tonne
constexpr double kPeriod = 0.5; // s
constexpr double kDampingRatio = 0.05;
constexpr double kRecordStep = 0.01; // s
constexpr double kDuration = 2.0;    // s

/// Half-sine pulse of 0.3 s and amplitude `peak` (default 3000 mm/s^2, 0.3 g), then zeros
/// to 2 s.
GroundAcceleration sine_pulse(double peak = 3000.0) {
  GroundAcceleration record;
  record.direction = Eigen::Vector3d::UnitX();
  record.dt = kRecordStep;
  const int samples = static_cast<int>(std::lround(kDuration / kRecordStep)) + 1;
  for (int i = 0; i < samples; ++i) {
    const double t = i * kRecordStep;
    record.acceleration.push_back(t <= 0.3 + 1e-12 ? peak * std::sin(kPi * t / 0.3) : 0.0);
  }
  return record;
}

/// Exact relative displacement of u'' + 2 xi w u' + w^2 u = -a_g(t) at the record's samples,
/// a_g linear between samples, from rest.
std::vector<double> exact_response(const GroundAcceleration& record, double w, double xi) {
  const double wd = w * std::sqrt(1.0 - xi * xi), h = record.dt;
  std::vector<double> displacement{0.0};
  double u = 0.0, v = 0.0;
  for (std::size_t i = 0; i + 1 < record.acceleration.size(); ++i) {
    // load p(tau) = p0 + p1 tau on [0, h]; particular solution A + B tau
    const double p0 = -record.acceleration[i];
    const double p1 = -(record.acceleration[i + 1] - record.acceleration[i]) / h;
    const double b = p1 / (w * w);
    const double a = (p0 - 2.0 * xi * w * b) / (w * w);
    const double c1 = u - a;
    const double c2 = (v - b + xi * w * c1) / wd;
    const double decay = std::exp(-xi * w * h), c = std::cos(wd * h), s = std::sin(wd * h);
    u = a + b * h + decay * (c1 * c + c2 * s);
    v = b + decay * ((-xi * w * c1 + wd * c2) * c + (-xi * w * c2 - wd * c1) * s);
    displacement.push_back(u);
  }
  return displacement;
}

struct PulseRun {
  double largest_error = 0.0;         ///< max over samples of |u - u_exact| (mm)
  double peak = 0.0;                  ///< max |u_exact|
  double largest_balance_error = 0.0; ///< max over steps of |error| / max |E_I| so far
  double final_input = 0.0;
  double final_damping = 0.0;
};

PulseRun run(int steps_per_sample) {
  const double w = 2.0 * kPi / kPeriod;
  model::Model model = test::single_oscillator(kMass, kMass * w * w);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  DampingSpec damping;
  damping.mass_factor = 2.0 * kDampingRatio * w; // c = a0 m = 2 xi w m
  analysis.set_damping(damping);
  const GroundAcceleration record = sine_pulse();
  analysis.add_ground_acceleration(record);
  const std::vector<double> exact = exact_response(record, w, kDampingRatio);
  const int ux = model::Model::global_dof(1, model::ux);
  PulseRun result;
  double largest_input = 0.0;
  const double dt = kRecordStep / steps_per_sample;
  for (std::size_t sample = 1; sample < exact.size(); ++sample) {
    for (int k = 0; k < steps_per_sample; ++k) {
      const TransientStepReport report = analysis.step(dt);
      EXPECT_TRUE(report.converged) << report.failure;
      const TransientEnergy& energy = analysis.energy();
      largest_input = std::max(largest_input, std::abs(energy.input));
      if (largest_input > 0.0) {
        result.largest_balance_error = std::max(result.largest_balance_error,
                                                std::abs(energy.absolute_error()) / largest_input);
      }
    }
    result.largest_error =
        std::max(result.largest_error, std::abs(analysis.displacement()[ux] - exact[sample]));
    result.peak = std::max(result.peak, std::abs(exact[sample]));
  }
  EXPECT_NEAR(analysis.time(), kDuration, 1e-9);
  result.final_input = analysis.energy().input;
  result.final_damping = analysis.energy().damping;
  return result;
}

TEST(TransientGroundMotion, DampedOscillatorConvergesToTheExactResponse) {
  const PulseRun coarse = run(2); // dt = 0.005 s, w dt = 0.063
  const PulseRun fine = run(4);   // dt = 0.0025 s
  ASSERT_GT(coarse.peak, 5.0);    // the pulse moves the oscillator (mm)
  // Newmark's period error (w dt)^2 / 12 accumulated over 4 cycles: about 2e-3 of the peak
  // at dt = 0.0025 s; measured below 1e-3.
  EXPECT_LT(fine.largest_error, 2e-3 * fine.peak);
  const double order = std::log2(coarse.largest_error / fine.largest_error);
  EXPECT_NEAR(order, 2.0, 0.1);
  // energy balance (exact for average acceleration up to the Newton tolerance)
  EXPECT_LT(coarse.largest_balance_error, 1e-6);
  EXPECT_LT(fine.largest_balance_error, 1e-6);
  // 1.7 s after the pulse, 5 % damping leaves about exp(-2 xi w t) = 0.12 of the energy
  EXPECT_GT(fine.final_input, 0.0);
  EXPECT_GT(fine.final_damping, 0.8 * fine.final_input);
  EXPECT_LT(fine.final_damping, fine.final_input);
  std::cout << "[ measured ] error at dt 0.005 s: " << coarse.largest_error / coarse.peak
            << " of the peak, at 0.0025 s: " << fine.largest_error / fine.peak << " (order "
            << order << "); balance " << fine.largest_balance_error << "\n";
}

TEST(TransientGroundMotion, YieldingBarsMisfitIsSetApartFromTheBalance) {
  // A mass on a steel bar (L = 1000 mm, A = 100 mm^2, S275 with linear mixed hardening) along
  // X, T = 0.5 s elastic, under a 0.05 g pulse: the bar yields back and forth (peak about
  // 9 dy). The record's steps do not land on the yield points, so the trapezoidal work of the bar's
  // stress (and of the nodal force: the bar's kinematics are linear along X) cuts the corners
  // of its bilinear path, while the law books the exact energy of each update: the difference
  // is the integration misfit. Newmark average acceleration balances the trapezoidal works
  // exactly (file comment of transient_analysis.cpp), so with the misfit set apart the error
  // is the Newton tolerance's.
  const material::SteelParameters steel = test::linear_mixed_steel();
  const double stiffness = steel.youngs_modulus * 100.0 / 1000.0;
  const double w = 2.0 * kPi / kPeriod;
  const double mass = stiffness / (w * w);
  model::Model model;
  const int ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(ground);
  const int node = test::add_x_oscillator_node(model, 1000.0, 0.0, mass);
  model.add_element(std::make_unique<element::CorotTruss<material::SteelUniaxial>>(
      std::array<int, 2>{ground, node}, model.coordinates(ground), model.coordinates(node), 100.0,
      material::SteelUniaxial(steel, 1000.0)));
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  analysis.add_ground_acceleration(sine_pulse(500.0));
  const double yield_displacement = steel.yield_stress / steel.youngs_modulus * 1000.0;
  const int ux = model::Model::global_dof(node, model::ux);
  double peak = 0.0;
  for (int step = 0; step < 400; ++step) {
    const TransientStepReport report = analysis.step(0.005);
    ASSERT_TRUE(report.converged) << report.failure;
    peak = std::max(peak, std::abs(analysis.displacement()[ux]));
  }
  const TransientEnergy& energy = analysis.energy();
  ASSERT_GT(peak, 2.0 * yield_displacement);
  ASSERT_GT(energy.dissipated, 0.1 * energy.gross_input);
  // the misfit is there and would dominate the error; set apart, the balance holds
  EXPECT_GT(std::abs(energy.integration_misfit), 1e-5 * energy.gross_input);
  EXPECT_LT(energy.relative_error(),
            1e-3 * std::abs(energy.integration_misfit) / energy.gross_input);
  std::cout << "[ measured ] peak " << peak / yield_displacement << " dy; misfit "
            << energy.integration_misfit / energy.gross_input << ", balance "
            << energy.relative_error() << " of the gross input\n";
}

TEST(TransientGroundMotion, GroundAccelerationIsReportedAtTheCommittedTime) {
  const double w = 2.0 * kPi / kPeriod;
  model::Model model = test::single_oscillator(kMass, kMass * w * w);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  analysis.add_ground_acceleration(sine_pulse());
  ASSERT_TRUE(analysis.step(0.15).converged);
  EXPECT_NEAR(analysis.ground_acceleration().x(), 3000.0 * std::sin(kPi * 0.5), 1e-9);
  EXPECT_EQ(analysis.ground_acceleration().y(), 0.0);
  // the fixed node does not move; the reaction there balances the spring
  const Eigen::VectorXd force = analysis.internal_force();
  EXPECT_NEAR(force[model::Model::global_dof(0, model::ux)],
              -force[model::Model::global_dof(1, model::ux)], 1e-9);
}

TEST(TransientGroundMotion, RejectsInvalidRecords) {
  model::Model model = test::single_oscillator(1.0, 100.0);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  GroundAcceleration record = sine_pulse();
  record.dt = 0.0;
  EXPECT_THROW(analysis.add_ground_acceleration(record), std::invalid_argument);
  record = sine_pulse();
  record.direction = Eigen::Vector3d(1.0, 1.0, 0.0);
  EXPECT_THROW(analysis.add_ground_acceleration(record), std::invalid_argument);
}

} // namespace
} // namespace brb::analysis
