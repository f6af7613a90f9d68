// Free vibration of linear oscillators under Newmark average acceleration and HHT-alpha,
// against the exact solution of the discrete recurrences: the amplification matrix A of the
// method (x_{n+1} = A x_n, x = (u, v, a)), built here from the method's defining equations
// (Hilber, Hughes and Taylor 1977; Chopra, Dynamics of Structures, sec. 5.4), independently
// of the implementation's incremental form; the period of the average-acceleration method,
// Omega = (2 / dt) atan(w dt / 2) (the Cayley transform of the oscillator; Chopra Table 5.3.1
// lists its period elongation).
#include "brb/analysis/transient_analysis.hpp"
#include "brb/element/zero_length_spring.hpp"
#include "brb/model/dof_map.hpp"
#include "support/oscillator_models.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::analysis {
namespace {

constexpr double kMass = 2.0; // tonne
constexpr double kPi = std::numbers::pi;

/// Amplification matrix of the undamped oscillator (w) for HHT-alpha with gamma = 1/2 - alpha,
/// beta = (1 - alpha)^2 / 4 (alpha = 0: Newmark average acceleration). Unknowns x1 = (u, v, a):
///   u1 - beta dt^2 a1 = u0 + dt v0 + (1/2 - beta) dt^2 a0
///   v1 - gamma dt a1 = v0 + (1 - gamma) dt a0
///   (1 + alpha) w^2 u1 + a1 = alpha w^2 u0
Eigen::Matrix3d amplification_matrix(double w, double dt, double alpha) {
  const double gamma = 0.5 - alpha;
  const double beta = 0.25 * (1.0 - alpha) * (1.0 - alpha);
  Eigen::Matrix3d left, right;
  left << 1.0, 0.0, -beta * dt * dt, 0.0, 1.0, -gamma * dt, (1.0 + alpha) * w * w, 0.0, 1.0;
  right << 1.0, dt, (0.5 - beta) * dt * dt, 0.0, 1.0, (1.0 - gamma) * dt, alpha * w * w, 0.0, 0.0;
  return left.partialPivLu().solve(right);
}

TransientSettings settings_for(double alpha) {
  TransientSettings settings;
  settings.integrator = alpha == 0.0 ? TimeIntegrator::newmark : TimeIntegrator::hht;
  settings.hht_alpha = alpha;
  return settings;
}

/// Displaces the oscillator node statically by `load` / k, then releases it.
void displace_and_release(TransientAnalysis& analysis, int node, double load) {
  Eigen::VectorXd force = Eigen::VectorXd::Zero(analysis.dof_map().full_dof_count());
  force[model::Model::global_dof(node, model::ux)] = load;
  const TransientStepReport report = analysis.apply_static_load(force, 1);
  ASSERT_TRUE(report.converged) << report.failure;
  analysis.remove_static_load();
}

void expect_recurrence(double alpha) {
  const double period = 0.5, w = 2.0 * kPi / period, stiffness = kMass * w * w;
  const double dt = 0.3 / w; // w dt = 0.3
  model::Model model = test::single_oscillator(kMass, stiffness);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3), settings_for(alpha));
  const double load = 1000.0, u0 = load / stiffness;
  displace_and_release(analysis, 1, load);
  const int ux = model::Model::global_dof(1, model::ux);
  ASSERT_NEAR(analysis.displacement()[ux], u0, 1e-12 * u0);
  // static work of the linear ramp: exactly 1/2 P u0 (the trapezoid is exact)
  EXPECT_NEAR(analysis.energy().static_work, 0.5 * load * u0, 1e-12 * load * u0);

  const Eigen::Matrix3d amplification = amplification_matrix(w, dt, alpha);
  Eigen::Vector3d state(u0, 0.0, -w * w * u0); // released at rest: a0 = -k u0 / m
  const Eigen::Vector3d scale(u0, w * u0, w * w * u0);
  for (int n = 1; n <= 200; ++n) {
    const TransientStepReport report = analysis.step(dt);
    ASSERT_TRUE(report.converged) << report.failure;
    state = amplification * state;
    EXPECT_NEAR(analysis.displacement()[ux], state[0], 1e-10 * scale[0]) << "step " << n;
    EXPECT_NEAR(analysis.velocity()[ux], state[1], 1e-10 * scale[1]) << "step " << n;
    EXPECT_NEAR(analysis.acceleration()[ux], state[2], 1e-10 * scale[2]) << "step " << n;
  }
  EXPECT_NEAR(analysis.time(), 200 * dt, 1e-12);
  EXPECT_TRUE(analysis.fallbacks().empty());
}

TEST(TransientFreeVibration, NewmarkFollowsItsAmplificationMatrix) {
  expect_recurrence(0.0);
}

TEST(TransientFreeVibration, HhtFollowsItsAmplificationMatrix) {
  expect_recurrence(-0.1);
}

TEST(TransientFreeVibration, AverageAccelerationPeriodAndAmplitude) {
  // (w u, v) turns by theta = 2 atan(w dt / 2) per step at constant radius: u_n = u0 cos(n theta)
  const double period = 0.5, w = 2.0 * kPi / period, stiffness = kMass * w * w;
  const double dt = period / 12.0; // coarse: w dt = 0.52, period elongation 2.3 %
  model::Model model = test::single_oscillator(kMass, stiffness);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  const double load = 500.0, u0 = load / stiffness;
  displace_and_release(analysis, 1, load);
  const int ux = model::Model::global_dof(1, model::ux);
  const double theta = 2.0 * std::atan(w * dt / 2.0);
  std::vector<double> history{u0};
  for (int n = 1; n <= 120; ++n) {
    ASSERT_TRUE(analysis.step(dt).converged);
    history.push_back(analysis.displacement()[ux]);
    EXPECT_NEAR(history.back(), u0 * std::cos(n * theta), 1e-10 * u0) << "step " << n;
    EXPECT_NEAR(analysis.velocity()[ux], -w * u0 * std::sin(n * theta), 1e-10 * w * u0);
  }
  // The period read from the response: for samples of a sinusoid,
  // cos(Omega dt) = (u_{n+1} + u_{n-1}) / (2 u_n), taken at a sample near a peak.
  const int n = 61;
  ASSERT_GT(std::abs(history[n]), 0.5 * u0);
  const double measured_period =
      2.0 * kPi * dt / std::acos((history[n + 1] + history[n - 1]) / (2.0 * history[n]));
  const double discrete_period = period * (w * dt / 2.0) / std::atan(w * dt / 2.0);
  EXPECT_NEAR(measured_period, discrete_period, 1e-10 * period);
  EXPECT_GT(discrete_period / period - 1.0, 0.02); // the elongation is real at this step
}

TEST(TransientFreeVibration, EnergyIsConstantWithoutDissipation) {
  const double period = 0.5, w = 2.0 * kPi / period, stiffness = kMass * w * w;
  model::Model model = test::single_oscillator(kMass, stiffness);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  displace_and_release(analysis, 1, 800.0);
  const double initial = analysis.energy().static_work;
  for (int n = 0; n < 300; ++n) {
    ASSERT_TRUE(analysis.step(0.013).converged);
    const TransientEnergy& energy = analysis.energy();
    EXPECT_NEAR(energy.kinetic + energy.stored, initial, 1e-12 * initial);
    EXPECT_NEAR(energy.absolute_error(), 0.0, 1e-12 * initial);
  }
}

TEST(TransientFreeVibration, TorsionalOscillatorIntegratesSpins) {
  // A rotational inertia J on a torsional spring about Z: about a fixed axis spins add up
  // and the spring's moment is exactly K theta (rotation.hpp: J^-T theta = theta), so the
  // rotation follows the same recurrence as a translation.
  const double inertia = 5.0e5, w = 2.0 * kPi / 0.4, stiffness = inertia * w * w, dt = 0.02;
  model::Model model;
  const int ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(ground);
  const int node = model.add_node({0.0, 0.0, 0.0});
  for (const model::Dof dof : {model::ux, model::uy, model::uz, model::rx, model::ry})
    model.fix(node, dof);
  model.add_mass(node, {0.0, 0.0, 0.0, 0.0, 0.0, inertia});
  model.add_element(std::make_unique<element::ZeroLengthSpring>(
      std::array<int, 2>{ground, node}, model.coordinates(ground), model.coordinates(node),
      element::SpringStiffness{0.0, 0.0, 0.0, 0.0, 0.0, stiffness}));
  TransientAnalysis analysis(model, model::DofMap::build(model, 3), settings_for(-0.05));
  Eigen::VectorXd moment = Eigen::VectorXd::Zero(model.dof_count());
  const int rz = model::Model::global_dof(node, model::rz);
  moment[rz] = 0.3 * stiffness; // 0.3 rad: a finite rotation
  ASSERT_TRUE(analysis.apply_static_load(moment, 1).converged);
  analysis.remove_static_load();
  ASSERT_NEAR(analysis.displacement()[rz], 0.3, 1e-12);
  const Eigen::Matrix3d amplification = amplification_matrix(w, dt, -0.05);
  Eigen::Vector3d state(0.3, 0.0, -w * w * 0.3);
  for (int n = 1; n <= 100; ++n) {
    ASSERT_TRUE(analysis.step(dt).converged);
    state = amplification * state;
    EXPECT_NEAR(analysis.displacement()[rz], state[0], 1e-10 * 0.3) << "step " << n;
    EXPECT_NEAR(analysis.velocity()[rz], state[1], 1e-10 * 0.3 * w) << "step " << n;
  }
}

TEST(TransientFreeVibration, HhtDampsTheStiffModeAndKeepsTheSoftOne) {
  // Two independent oscillators: w dt = 0.05 (soft) and w dt = 20 (stiff). HHT's spectral
  // radius at w dt -> infinity is (1 + alpha) / (1 - alpha) = 0.818 for alpha = -0.1
  // (Hilber et al. 1977), so the stiff energy falls by about 0.818^(2 n); Newmark's is 1.
  const double dt = 0.01, soft_w = 0.05 / dt, stiff_w = 20.0 / dt, mass = 1.0;
  const auto run = [&](double alpha, double& soft_ratio, double& stiff_ratio, double& total_ratio) {
    model::Model model;
    const int ground = model.add_node({0.0, 0.0, 0.0});
    model.fix_all(ground);
    const int soft = test::add_x_oscillator_node(model, 1000.0, 0.0, mass);
    const int stiff = test::add_x_oscillator_node(model, 2000.0, 0.0, mass);
    test::add_x_spring(model, ground, soft, mass * soft_w * soft_w);
    test::add_x_spring(model, ground, stiff, mass * stiff_w * stiff_w);
    TransientAnalysis analysis(model, model::DofMap::build(model, 3), settings_for(alpha));
    Eigen::VectorXd force = Eigen::VectorXd::Zero(model.dof_count());
    // displacements of millimetres: node positions are absolute (1000 and 2000 mm), so a
    // displacement u carries a round-off of 1e-16 x 2000 mm / u
    force[model::Model::global_dof(soft, model::ux)] = 100.0;
    force[model::Model::global_dof(stiff, model::ux)] = 1e7;
    ASSERT_TRUE(analysis.apply_static_load(force, 1).converged);
    analysis.remove_static_load();
    const auto oscillator_energy = [&](int node, double w) {
      const int dof = model::Model::global_dof(node, model::ux);
      const double u = analysis.displacement()[dof], v = analysis.velocity()[dof];
      return 0.5 * mass * (w * w * u * u + v * v);
    };
    const double soft_start = oscillator_energy(soft, soft_w);
    const double stiff_start = oscillator_energy(stiff, stiff_w);
    const double total_start = analysis.energy().static_work;
    for (int n = 0; n < 60; ++n)
      ASSERT_TRUE(analysis.step(dt).converged);
    soft_ratio = oscillator_energy(soft, soft_w) / soft_start;
    stiff_ratio = oscillator_energy(stiff, stiff_w) / stiff_start;
    total_ratio = (analysis.energy().kinetic + analysis.energy().stored) / total_start;
  };
  // The discrete energy ratios after 60 steps from the amplification matrices.
  const auto recurrence_ratio = [&](double w, double alpha) {
    const Eigen::Matrix3d amplification = amplification_matrix(w, dt, alpha);
    Eigen::Vector3d state(1.0, 0.0, -w * w);
    for (int n = 0; n < 60; ++n)
      state = amplification * state;
    return (w * w * state[0] * state[0] + state[1] * state[1]) / (w * w);
  };
  double soft = 0.0, stiff = 0.0, total = 0.0;
  run(0.0, soft, stiff, total);
  EXPECT_NEAR(soft, 1.0, 1e-12);
  EXPECT_NEAR(stiff, 1.0, 1e-12);
  EXPECT_NEAR(total, 1.0, 1e-12);
  run(-0.1, soft, stiff, total);
  EXPECT_NEAR(soft, recurrence_ratio(soft_w, -0.1), 1e-10);
  EXPECT_NEAR(stiff, recurrence_ratio(stiff_w, -0.1), 1e-10);
  EXPECT_LT(stiff, 1e-6); // 0.818^120 = 3e-11 in the limit
  EXPECT_GT(soft, 0.99);  // the low mode keeps its energy
  EXPECT_LT(soft, 1.0);
}

} // namespace
} // namespace brb::analysis
