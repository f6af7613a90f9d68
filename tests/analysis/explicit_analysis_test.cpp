// ExplicitAnalysis (central difference through Boost.Odeint's velocity Verlet) against the
// exact discrete central-difference solution, closed forms of linear oscillators, an exact
// piecewise-linear-excitation solution (independent integration in this file), modal
// superposition of a two-storey shear frame, and the stability limits of the method.
#include "brb/analysis/explicit_analysis.hpp"

#include "brb/element/zero_length_spring.hpp"
#include "brb/model/dof_map.hpp"
#include "brb/model/model.hpp"
#include "support/beam_models.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace brb::analysis {
namespace {

using element::NodeConfiguration;
using element::Vector3;
using model::Dof;
using model::Model;

constexpr double kPi = std::numbers::pi;

/// Node 1 (mass `mass` in ux, every other DOF restrained) on a spring `stiffness` in ux to
/// the restrained node 0: a linear SDOF oscillator, one equation.
std::unique_ptr<Model> make_sdof(double mass, double stiffness) {
  auto model = std::make_unique<Model>();
  const int ground = model->add_node(Vector3::Zero());
  const int node = model->add_node(Vector3::Zero());
  model->fix_all(ground);
  for (const Dof dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
    model->fix(node, dof);
  model->add_mass(node, {mass, 0.0, 0.0, 0.0, 0.0, 0.0});
  model->add_element(std::make_unique<element::ZeroLengthSpring>(
      std::array<int, 2>{ground, node}, Vector3::Zero(), Vector3::Zero(),
      element::SpringStiffness{stiffness, 0.0, 0.0, 0.0, 0.0, 0.0}));
  return model;
}

/// Full-DOF displacement of node `node` along `dof`.
double node_value(const Eigen::VectorXd& full, int node, Dof dof) {
  return full[Model::global_dof(node, dof)];
}

/// Exact response of m u'' + c u' + k u = p(t) with p linear between samples (an
/// independent computation: the particular solution of a linear load (p0 + s tau)/k - c s/k^2
/// plus the damped free vibration that matches the state at the interval's start; Chopra,
/// Dynamics of Structures, sec. 5.2 "interpolation of excitation"). Underdamped (xi < 1).
struct ExactOscillator {
  double mass, damping, stiffness;
  double u = 0.0, v = 0.0;

  void advance(double p_start, double p_end, double dt) {
    const double w = std::sqrt(stiffness / mass);
    const double xi = damping / (2.0 * mass * w);
    const double wd = w * std::sqrt(1.0 - xi * xi);
    const double slope = (p_end - p_start) / dt;
    const double particular_u0 = p_start / stiffness - damping * slope / (stiffness * stiffness);
    const double particular_v = slope / stiffness;
    const double a = u - particular_u0;
    const double b = (v - particular_v + xi * w * a) / wd;
    const double decay = std::exp(-xi * w * dt);
    const double c = std::cos(wd * dt), s = std::sin(wd * dt);
    const double homogeneous_u = decay * (a * c + b * s);
    const double homogeneous_v = decay * ((-xi * w) * (a * c + b * s) + wd * (-a * s + b * c));
    u = particular_u0 + particular_v * dt + homogeneous_u;
    v = particular_v + homogeneous_v;
  }
};

/// A ground acceleration record: two decaying sines (mm/s^2), sampled at `dt` for `duration`.
GroundAcceleration make_record(double dt, double duration) {
  GroundAcceleration record;
  record.direction = Eigen::Vector3d::UnitX();
  record.dt = dt;
  const int samples = static_cast<int>(std::round(duration / dt)) + 1;
  for (int i = 0; i < samples; ++i) {
    const double t = i * dt;
    record.acceleration.push_back(3000.0 * std::sin(2.0 * kPi * 1.7 * t) * std::exp(-t) +
                                  2000.0 * std::sin(2.0 * kPi * 4.3 * t));
  }
  return record;
}

double nrms(const std::vector<double>& value, const std::vector<double>& reference) {
  double error = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < value.size(); ++i) {
    error += (value[i] - reference[i]) * (value[i] - reference[i]);
    norm += reference[i] * reference[i];
  }
  return std::sqrt(error / norm);
}

// --- SDOF free vibration ------------------------------------------------------------------

TEST(ExplicitAnalysis, FreeVibrationFollowsTheExactCentralDifferenceRecurrence) {
  const double mass = 2.0, stiffness = 800.0; // w = 20 rad/s
  const double w = std::sqrt(stiffness / mass);
  const double dt = 0.1 / w; // w dt = 0.1
  auto model = make_sdof(mass, stiffness);
  ExplicitSettings settings;
  settings.time_step = dt;
  ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
  const double u0 = 5.0;
  auto nodes = model::initial_configuration(*model);
  nodes[1].position.x() += u0;
  analysis.set_initial_state(nodes, Eigen::VectorXd::Zero(model->dof_count()));

  // Central difference on u'' + w^2 u = 0 from (u0, 0): u_n = u0 cos(n Omega dt) exactly,
  // with cos(Omega dt) = 1 - (w dt)^2 / 2 (Hughes, The Finite Element Method, ch. 9).
  const double omega_dt = std::acos(1.0 - 0.5 * (w * dt) * (w * dt));
  // the method's period elongation: Omega / w = 1 - (w dt)^2 / 24 + O((w dt)^4)
  EXPECT_NEAR(omega_dt / (w * dt), 1.0 + 0.01 / 24.0, 1e-5);
  const int steps = static_cast<int>(std::ceil(3.0 * 2.0 * kPi / (w * dt))); // 3 periods
  double largest_closed_form_error = 0.0;
  for (int n = 1; n <= steps; ++n) {
    ASSERT_TRUE(analysis.step().completed);
    const double u = node_value(analysis.displacement(), 1, model::ux);
    EXPECT_NEAR(u, u0 * std::cos(n * omega_dt), 1e-9 * u0) << "step " << n;
    // Against cos(w t): the phase error n dt |Omega - w| bounds the difference
    // (|cos a - cos b| <= |a - b|), O((w dt)^2) per radian.
    const double t = analysis.time();
    const double bound = u0 * n * std::abs(omega_dt - w * dt);
    const double error = std::abs(u - u0 * std::cos(w * t));
    EXPECT_LE(error, bound * (1.0 + 1e-6) + 1e-12) << "step " << n;
    largest_closed_form_error = std::max(largest_closed_form_error, error);
  }
  // the bound is attained in order of magnitude: after 3 periods the phase error is
  // 6 pi (w dt)^2 / 24 = 7.9e-3 rad
  EXPECT_GT(largest_closed_form_error, 0.5 * u0 * 6.0 * kPi * 0.01 / 24.0);
  EXPECT_NEAR(analysis.time(), steps * dt, 1e-12);
  // the velocity is the derivative of the discrete solution's interpolant
  EXPECT_TRUE(analysis.velocity().allFinite());
}

TEST(ExplicitAnalysis, HeldStaticLoadFromRestAndAStaticInitialState) {
  const double mass = 1.0, stiffness = 400.0, load = 1200.0; // static displacement 3 mm
  const double w = std::sqrt(stiffness / mass);
  const double dt = 0.2 / w;
  Eigen::VectorXd full_load = Eigen::VectorXd::Zero(12);
  full_load[Model::global_dof(1, model::ux)] = load;
  ExplicitSettings settings;
  settings.time_step = dt;
  {
    // from rest: u_n = (P/k)(1 - cos(n Omega dt)), the recurrence above about P/k
    auto model = make_sdof(mass, stiffness);
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
    analysis.set_static_load(full_load);
    const double omega_dt = std::acos(1.0 - 0.5 * (w * dt) * (w * dt));
    for (int n = 1; n <= 200; ++n) {
      ASSERT_TRUE(analysis.step().completed);
      EXPECT_NEAR(node_value(analysis.displacement(), 1, model::ux),
                  load / stiffness * (1.0 - std::cos(n * omega_dt)), 1e-9 * load / stiffness);
    }
    // Energy: the internal and static work are exact for a linear spring; the kinetic
    // energy differs from the trapezoidal work of M a by m dt^2/8 (a_N^2 - a_0^2), a
    // non-accumulating term bounded by (w dt)^2 / 8 * P^2 / k (|a| <= P / m)
    EXPECT_LE(std::abs(analysis.energy().absolute_error()),
              (1.0 + 1e-9) * 0.125 * (w * dt) * (w * dt) * load * load / stiffness);
    EXPECT_GT(analysis.energy().static_work, 0.0);
  }
  {
    // from the static state under the same load (found on a twin model, whose element
    // states are taken over): it stays there, at rest
    auto model = make_sdof(mass, stiffness);
    const auto twin = make_sdof(mass, stiffness);
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
    auto nodes = model::initial_configuration(*model);
    nodes[1].position.x() += load / stiffness;
    analysis.initialise_static(*twin, nodes, full_load);
    ASSERT_TRUE(analysis.run_to(100 * dt).completed);
    EXPECT_NEAR(node_value(analysis.displacement(), 1, model::ux), load / stiffness, 1e-12);
    EXPECT_NEAR(node_value(analysis.internal_force(), 1, model::ux), load, 1e-9);
    EXPECT_NEAR(analysis.energy().absolute_error(), 0.0, 1e-9);
  }
  {
    // a state out of equilibrium is refused, naming the equation
    auto model = make_sdof(mass, stiffness);
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
    auto nodes = model::initial_configuration(*model);
    nodes[1].position.x() += 0.5 * load / stiffness;
    try {
      analysis.initialise_static(nodes, full_load);
      FAIL() << "an unbalanced static state was accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("node 1 ux"), std::string::npos) << error.what();
    }
  }
}

// --- stability ----------------------------------------------------------------------------

TEST(ExplicitAnalysis, StableStepOfAnUndampedOscillator) {
  const double mass = 3.0, stiffness = 1200.0; // w = 20 rad/s
  const double w = std::sqrt(stiffness / mass);
  {
    auto model = make_sdof(mass, stiffness);
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3));
    // automatic: 0.9 * 2 / w (central difference: stable for w dt <= 2)
    EXPECT_NEAR(analysis.stable_time_step(), 0.9 * 2.0 / w, 1e-12);
    EXPECT_NEAR(analysis.stable_step_estimate().max_frequency, w, 1e-9 * w);
    EXPECT_DOUBLE_EQ(analysis.time_step(), analysis.stable_time_step());
  }
  {
    // a requested step above the stable one is refused
    auto model = make_sdof(mass, stiffness);
    ExplicitSettings settings;
    settings.time_step = 2.02 / w;
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
    EXPECT_THROW(analysis.step(), std::invalid_argument);
  }
  for (const double factor : {0.99, 1.01}) {
    // run anyway: w dt = 1.98 stays bounded by u0 (u_n = u0 cos(n Omega dt)); w dt = 2.02
    // has an amplification factor of modulus (|b| + sqrt(b^2 - 4)) / 2 = 1.22 with
    // b = 2 - (w dt)^2, and grows until the state is non-finite, which stops the run
    auto model = make_sdof(mass, stiffness);
    ExplicitSettings settings;
    settings.time_step = factor * 2.0 / w;
    settings.refuse_unstable_step = false;
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
    const double u0 = 1.0;
    auto nodes = model::initial_configuration(*model);
    nodes[1].position.x() += u0;
    analysis.set_initial_state(nodes, Eigen::VectorXd::Zero(model->dof_count()));
    double largest = 0.0;
    bool stopped = false;
    for (int n = 0; n < 5000 && !stopped; ++n) {
      const ExplicitStepReport report = analysis.step();
      stopped = !report.completed;
      if (!stopped)
        largest = std::max(largest, std::abs(node_value(analysis.displacement(), 1, model::ux)));
    }
    if (factor < 1.0) {
      EXPECT_FALSE(stopped);
      EXPECT_LE(largest, u0 * (1.0 + 1e-9));
    } else {
      EXPECT_TRUE(stopped);
      ASSERT_TRUE(analysis.failure().has_value());
      EXPECT_NE(analysis.failure()->reason.find("non-finite"), std::string::npos)
          << analysis.failure()->reason;
      EXPECT_GT(largest, 1e100 * u0);
      EXPECT_TRUE(analysis.displacement().allFinite()); // the last finite state is kept
      EXPECT_FALSE(analysis.step().completed);          // and the run stays stopped
    }
  }
}

TEST(ExplicitAnalysis, StableStepOfADampedOscillator) {
  // Stiffness-proportional damping, evaluated at v_{n+1/2}: stable for
  // dt <= (2 / w)(sqrt(1 + xi^2) - xi) (Belytschko, Liu, Moran, Nonlinear Finite Elements,
  // ch. 6). Mass-proportional damping, taken at v_{n+1} (diagonal), keeps 2 / w.
  const double mass = 1.0, stiffness = 100.0; // w = 10 rad/s
  const double w = 10.0;
  const double xi = 0.2;
  for (const bool stiffness_part : {false, true}) {
    DampingSpec damping;
    if (stiffness_part)
      damping.stiffness_factor = 2.0 * xi / w; // xi(w) = a1 w / 2
    else
      damping.mass_factor = 2.0 * xi * w; // xi(w) = a0 / (2 w)
    const double critical = stiffness_part ? 2.0 / w * (std::sqrt(1.0 + xi * xi) - xi) : 2.0 / w;
    {
      auto model = make_sdof(mass, stiffness);
      ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3));
      analysis.set_damping(damping);
      EXPECT_NEAR(analysis.stable_step_estimate().damping_ratio, stiffness_part ? xi : 0.0, 1e-12);
      EXPECT_NEAR(analysis.stable_time_step(), 0.9 * critical, 1e-12);
    }
    for (const double factor : {0.98, 1.02}) {
      auto model = make_sdof(mass, stiffness);
      ExplicitSettings settings;
      settings.time_step = factor * critical;
      settings.refuse_unstable_step = false;
      ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
      analysis.set_damping(damping);
      auto nodes = model::initial_configuration(*model);
      nodes[1].position.x() += 1.0;
      analysis.set_initial_state(nodes, Eigen::VectorXd::Zero(model->dof_count()));
      bool grew = false;
      for (int n = 0; n < 2000 && !grew; ++n) {
        if (!analysis.step().completed)
          break;
        grew = std::abs(node_value(analysis.displacement(), 1, model::ux)) > 1e3;
      }
      EXPECT_EQ(grew, factor > 1.0) << "factor " << factor << " stiffness part " << stiffness_part;
    }
  }
}

// --- ground motion ------------------------------------------------------------------------

TEST(ExplicitAnalysis, DampedOscillatorUnderGroundMotionAgainstTheExactSolution) {
  const double mass = 1.5, period = 0.4, xi = 0.05;
  const double w = 2.0 * kPi / period;
  const double stiffness = mass * w * w;
  const GroundAcceleration record = make_record(0.01, 3.0);

  struct Run {
    double error = 0.0;   ///< NRMS of the displacement history against the exact one
    double balance = 0.0; ///< largest |energy error| / largest |ground input|
  };
  // the exact response to the linearly interpolated record, at every explicit step
  const auto run = [&](int substeps, const DampingSpec& damping) {
    auto model = make_sdof(mass, stiffness);
    ExplicitSettings settings;
    settings.time_step = record.dt / substeps;
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
    analysis.set_damping(damping);
    analysis.add_ground_acceleration(record);
    ExactOscillator exact{mass, 2.0 * xi * mass * w, stiffness};
    std::vector<double> explicit_u, exact_u;
    double largest_input = 0.0, largest_error = 0.0;
    const double end = record.dt * static_cast<double>(record.acceleration.size() - 1);
    while (analysis.time() < end - 1e-9) {
      const double t = analysis.time();
      if (!analysis.step().completed)
        return Run{1.0, 1.0};
      exact.advance(-mass * record.at(t), -mass * record.at(analysis.time()), analysis.time() - t);
      explicit_u.push_back(node_value(analysis.displacement(), 1, model::ux));
      exact_u.push_back(exact.u);
      largest_input = std::max(largest_input, std::abs(analysis.energy().input));
      largest_error = std::max(largest_error, std::abs(analysis.energy().absolute_error()));
    }
    return Run{nrms(explicit_u, exact_u), largest_error / largest_input};
  };
  DampingSpec mass_damping; // xi(w) = a0 / (2 w)
  mass_damping.mass_factor = 2.0 * xi * w;
  DampingSpec stiffness_damping; // xi(w) = a1 w / 2
  stiffness_damping.stiffness_factor = 2.0 * xi / w;

  // Mass-proportional damping at v_{n+1}: second order. w dt = 0.016 at 10 substeps.
  const Run mass_coarse = run(5, mass_damping);
  const Run mass_fine = run(10, mass_damping);
  EXPECT_LT(mass_fine.error, 1e-3);
  EXPECT_GT(mass_coarse.error / mass_fine.error, 3.5); // 4 for second order
  // Stiffness-proportional damping at v_{n+1/2}: the half-step lag of the damping
  // velocity makes the history first order in dt
  const Run stiffness_coarse = run(5, stiffness_damping);
  const Run stiffness_fine = run(10, stiffness_damping);
  EXPECT_LT(stiffness_fine.error, 1e-2);
  EXPECT_GT(stiffness_coarse.error / stiffness_fine.error, 1.8); // 2 for first order
  EXPECT_LT(stiffness_coarse.error / stiffness_fine.error, 2.2);
  // energy balance of the runs, relative to the largest ground input
  for (const Run& result : {mass_coarse, mass_fine, stiffness_coarse, stiffness_fine})
    EXPECT_LT(result.balance, 1e-3);
}

TEST(ExplicitAnalysis, TwoStoreyShearFrameAgainstModalSuperposition) {
  // TransientAnalysis is not implemented on main yet: the reference is the modal
  // superposition of the undamped frame, each mode integrated exactly (ExactOscillator).
  const double m1 = 12.0, m2 = 8.0, k1 = 3.0e4, k2 = 2.0e4; // tonne, N/mm
  Model model;
  const int ground = model.add_node(Vector3::Zero());
  const int first = model.add_node(Vector3(0.0, 0.0, 3000.0));
  const int roof = model.add_node(Vector3(0.0, 0.0, 6000.0));
  model.fix_all(ground);
  for (const int node : {first, roof}) {
    for (const Dof dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
      model.fix(node, dof);
  }
  model.add_mass(first, {m1, 0.0, 0.0, 0.0, 0.0, 0.0});
  model.add_mass(roof, {m2, 0.0, 0.0, 0.0, 0.0, 0.0});
  for (const auto& [i, j, k] : {std::tuple{ground, first, k1}, std::tuple{first, roof, k2}}) {
    model.add_element(std::make_unique<element::ZeroLengthSpring>(
        std::array<int, 2>{i, j}, model.coordinates(i), model.coordinates(j),
        element::SpringStiffness{k, 0.0, 0.0, 0.0, 0.0, 0.0}));
  }
  const GroundAcceleration record = make_record(0.01, 3.0);

  // modes: K phi = w^2 M phi, mass-normalised; participation Gamma_i = phi_i^T M 1
  Eigen::Matrix2d stiffness_matrix{{k1 + k2, -k2}, {-k2, k2}};
  Eigen::Matrix2d mass_matrix{{m1, 0.0}, {0.0, m2}};
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> modes(stiffness_matrix,
                                                                        mass_matrix);
  const Eigen::Vector2d frequencies = modes.eigenvalues().cwiseSqrt();
  const Eigen::Matrix2d shapes = modes.eigenvectors();
  const Eigen::Vector2d participation = shapes.transpose() * mass_matrix * Eigen::Vector2d::Ones();

  ExplicitAnalysis probe(model, model::DofMap::build(model, 3));
  // the stable step of the lumped system: 0.9 * 2 / w_max
  EXPECT_NEAR(probe.stable_time_step(), 0.9 * 2.0 / frequencies.maxCoeff(),
              1e-6 * probe.stable_time_step());
  // 5 % Rayleigh damping in both modes (classical damping: the modes stay uncoupled, mode i
  // has c_i = a0 + a1 w_i^2 per unit modal mass); dt = record dt / 10 (w_2 dt = 0.074): the
  // phase error (w dt)^2 / 24 per radian accumulates over the 3 s record, and the stiffness
  // part's half-step lag is first order
  const auto [a0, a1] = rayleigh_coefficients(frequencies[0], 0.05, frequencies[1], 0.05);
  DampingSpec damping;
  damping.mass_factor = a0;
  damping.stiffness_factor = a1;
  ExplicitSettings settings;
  settings.time_step = record.dt / 10.0;
  ExplicitAnalysis analysis(model, model::DofMap::build(model, 3), settings);
  analysis.set_damping(damping);
  analysis.add_ground_acceleration(record);

  std::vector<ExactOscillator> modal;
  for (int i = 0; i < 2; ++i) {
    const double w2 = frequencies[i] * frequencies[i];
    modal.push_back({1.0, a0 + a1 * w2, w2});
  }
  std::vector<double> roof_explicit, roof_modal;
  const double end = record.dt * static_cast<double>(record.acceleration.size() - 1);
  while (analysis.time() < end - 1e-9) {
    const double t = analysis.time();
    ASSERT_TRUE(analysis.step().completed);
    double roof_displacement = 0.0;
    for (int i = 0; i < 2; ++i) {
      modal[i].advance(-participation[i] * record.at(t),
                       -participation[i] * record.at(analysis.time()), analysis.time() - t);
      roof_displacement += shapes(1, i) * modal[i].u;
    }
    roof_explicit.push_back(node_value(analysis.displacement(), roof, model::ux));
    roof_modal.push_back(roof_displacement);
  }
  EXPECT_LT(nrms(roof_explicit, roof_modal), 0.01);
  EXPECT_GT(analysis.energy().damping, 0.0);
  EXPECT_LT(std::abs(analysis.energy().absolute_error()), 1e-3 * std::abs(analysis.energy().input));
}

// --- mass scaling -------------------------------------------------------------------------

TEST(ExplicitAnalysis, MassScaledRotationRunsAtTheTranslationalStep) {
  // A planar cantilever (X-Z), one elastic co-rotational element along x, tip mass in ux and
  // uz and no rotational inertia: the tip rotation ry is an equation without mass.
  const double length = 3000.0, mass = 5.0;
  section::ElasticSectionProperties properties;
  properties.axial_stiffness = 2.0e9;      // E A (N)
  properties.bending_stiffness_y = 2.0e13; // E I (N mm^2)
  properties.bending_stiffness_z = 2.0e13;
  properties.torsional_stiffness = 1.0e13;
  const auto make_model = [&]() {
    auto model = std::make_unique<Model>();
    test::add_elastic_beam(*model, Vector3::Zero(), length, 1, properties);
    model->fix_all(0);
    model->add_mass(1, {mass, 0.0, mass, 0.0, 0.0, 0.0});
    return model;
  };
  const double axial = std::sqrt(properties.axial_stiffness / (length * mass));
  const double ei = properties.bending_stiffness_y;
  {
    // without mass scaling the massless rotation is an input error naming the equation
    auto model = make_model();
    ExplicitSettings settings;
    settings.mass_scaling = false;
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 2), settings);
    try {
      analysis.prepare();
      FAIL() << "a massless equation was accepted without mass scaling";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("node 1 ry"), std::string::npos) << error.what();
    }
  }
  auto model = make_model();
  ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 2));
  // the scaling target: 0.9 * 2 / w of the stiffest equation with mass (axial, EA/(L m));
  // the rotation gets m = R dt^2, R = sum_j |K_ij| of its row (no damping): 4 EI / L on the
  // diagonal and |-6 EI / L^2| coupling it to the tip's uz (cubic Hermite beam)
  const double target = 0.9 * 2.0 / axial;
  const MassScalingReport& scaling = analysis.mass_scaling();
  EXPECT_EQ(scaling.scaled_equations, 1);
  const double added = (4.0 * ei / length + 6.0 * ei / (length * length)) * target * target;
  EXPECT_NEAR(scaling.added_rotational_inertia, added, 1e-9 * added);
  EXPECT_DOUBLE_EQ(scaling.rotational_fraction(), 1.0);
  EXPECT_DOUBLE_EQ(scaling.translational_fraction(), 0.0);
  EXPECT_DOUBLE_EQ(scaling.translational_mass, 2.0 * mass);
  // the scaled rotation does not limit the step: the axial mode does
  EXPECT_NEAR(analysis.stable_step_estimate().max_frequency, axial, 1e-6 * axial);
  EXPECT_NEAR(analysis.stable_time_step(), target, 1e-6 * target);

  // Lateral vibration of the scaled system: K = [12 EI/L^3, -6 EI/L^2; -6 EI/L^2, 4 EI/L]
  // with M = diag(m, added) (sign of the coupling irrelevant to the frequencies); without
  // the added inertia the lateral frequency is sqrt(3 EI / (m L^3)).
  const double l = length;
  Eigen::Matrix2d lateral_stiffness{{12.0 * ei / (l * l * l), -6.0 * ei / (l * l)},
                                    {-6.0 * ei / (l * l), 4.0 * ei / l}};
  Eigen::Matrix2d lateral_mass{{mass, 0.0}, {0.0, added}};
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> lateral(lateral_stiffness,
                                                                          lateral_mass);
  const double scaled_frequency = std::sqrt(lateral.eigenvalues()[0]);
  const double massless_frequency = std::sqrt(3.0 * ei / (mass * l * l * l));
  const double dt = analysis.time_step();
  // central difference raises each mode's frequency: Omega = (2/dt) asin(w dt / 2)
  const double expected = 2.0 / dt * std::asin(0.5 * scaled_frequency * dt);
  ASSERT_GT(massless_frequency / expected - 1.0, 5e-3); // the shift is measurable

  // small amplitude: tip velocity in z, zero displacement
  auto nodes = model::initial_configuration(*model);
  Eigen::VectorXd velocity = Eigen::VectorXd::Zero(model->dof_count());
  const double v0 = 1.0; // mm/s, amplitude v0 / w = 0.05 mm
  velocity[Model::global_dof(1, model::uz)] = v0;
  // a fresh analysis: set-up comes before the queries above
  auto fresh = make_model();
  ExplicitAnalysis run(*fresh, model::DofMap::build(*fresh, 2));
  run.set_initial_state(nodes, velocity);
  const double periods = 5.0;
  std::vector<double> crossings;
  double previous = 0.0, largest = 0.0;
  while (run.time() < periods * 2.0 * kPi / massless_frequency) {
    const double t = run.time();
    ASSERT_TRUE(run.step().completed);
    const double w_tip = node_value(run.displacement(), 1, model::uz);
    largest = std::max(largest, std::abs(w_tip));
    if (t > 0.0 && previous * w_tip < 0.0) // linear interpolation of the zero
      crossings.push_back(t + (run.time() - t) * previous / (previous - w_tip));
    previous = w_tip;
  }
  EXPECT_DOUBLE_EQ(run.time_step(), dt);
  ASSERT_GE(crossings.size(), 8u);
  const double measured =
      kPi * static_cast<double>(crossings.size() - 1) / (crossings.back() - crossings.front());
  EXPECT_NEAR(measured, expected, 2e-3 * expected);
  EXPECT_LT(largest, 1.05 * v0 / scaled_frequency); // bounded: no growth
  EXPECT_LT(std::abs(run.energy().absolute_error()), 1e-2 * run.energy().static_work);
}

TEST(ExplicitAnalysis, LargeRotationsOfAMassScaledCantileverConserveEnergy) {
  // The cantilever above swung to a tip deflection of about L/6 (rotations of 0.25 rad):
  // the co-rotational beam is geometrically nonlinear and the spins accumulate on the
  // nodal triads. Undamped and unloaded, kinetic + stored energy keeps its initial value up
  // to the method's truncation, second order in dt (the trapezoidal work of the nonlinear
  // internal force and the term dt^2/8 a^T M a): halving the step divides the error by ~4.
  const double length = 3000.0, mass = 5.0;
  section::ElasticSectionProperties properties;
  properties.axial_stiffness = 2.0e9;
  properties.bending_stiffness_y = 2.0e13;
  properties.bending_stiffness_z = 2.0e13;
  properties.torsional_stiffness = 1.0e13;
  const double lateral = std::sqrt(3.0 * 2.0e13 / (mass * length * length * length));
  struct Run {
    double deflection = 0.0, rotation = 0.0, energy_error = 0.0; ///< largest; error / initial
    std::size_t fallbacks = 0;
  };
  const auto run = [&](double time_step) {
    Model model;
    test::add_elastic_beam(model, Vector3::Zero(), length, 1, properties);
    model.fix_all(0);
    model.add_mass(1, {mass, 0.0, mass, 0.0, 0.0, 0.0});
    ExplicitSettings settings;
    settings.time_step = time_step; // 0: automatic
    ExplicitAnalysis analysis(model, model::DofMap::build(model, 2), settings);
    Eigen::VectorXd velocity = Eigen::VectorXd::Zero(model.dof_count());
    velocity[Model::global_dof(1, model::uz)] = 500.0 * lateral; // amplitude ~ 500 mm
    analysis.set_initial_state(model::initial_configuration(model), velocity);
    analysis.prepare();
    const double initial = analysis.energy().static_work; // the initial kinetic energy
    EXPECT_NEAR(initial, 0.5 * mass * velocity.squaredNorm(), 1e-9 * initial);
    Run result;
    while (analysis.time() < 3.0 * 2.0 * kPi / lateral) {
      if (!analysis.step().completed)
        return Run{0.0, 0.0, 1.0, 0};
      const Eigen::VectorXd u = analysis.displacement();
      result.deflection = std::max(result.deflection, std::abs(node_value(u, 1, model::uz)));
      result.rotation = std::max(result.rotation, std::abs(node_value(u, 1, model::ry)));
      result.energy_error =
          std::max(result.energy_error, std::abs(analysis.energy().absolute_error()) / initial);
    }
    result.fallbacks = analysis.fallbacks().size();
    return result;
  };
  const Run automatic = run(0.0);
  const double stable = 0.9 * 2.0 / std::sqrt(properties.axial_stiffness / (length * mass));
  const Run halved = run(0.5 * stable);
  EXPECT_GT(automatic.deflection, length / 8.0); // large: the nonlinearity matters
  EXPECT_GT(automatic.rotation, 0.2);
  EXPECT_LT(automatic.energy_error, 3e-2);
  EXPECT_LT(halved.energy_error, 0.35 * automatic.energy_error); // second order
  EXPECT_EQ(automatic.fallbacks, 0u); // the step stayed stable (checked every 10 steps)
}

TEST(ExplicitAnalysis, StiffnessDampingOfTheIncludedElementsOnly) {
  // Two parallel springs on an SDOF, k_a included in the stiffness-proportional damping,
  // k_b not: C = a1 k_a, xi = a1 k_a / (2 m w) with w = sqrt((k_a + k_b) / m). The free
  // vibration is the exact damped one (Chopra, sec. 2.2); checked over 5 periods at
  // w dt = 0.02 (the first-order lag of the damping velocity is then negligible).
  const double mass = 1.0, k_a = 300.0, k_b = 100.0, a1 = 0.004;
  Model model;
  model.add_node(Vector3::Zero());
  model.add_node(Vector3::Zero());
  model.fix_all(0);
  for (const Dof dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
    model.fix(1, dof);
  model.add_mass(1, {mass, 0.0, 0.0, 0.0, 0.0, 0.0});
  for (const double k : {k_a, k_b}) {
    model.add_element(std::make_unique<element::ZeroLengthSpring>(
        std::array<int, 2>{0, 1}, Vector3::Zero(), Vector3::Zero(),
        element::SpringStiffness{k, 0.0, 0.0, 0.0, 0.0, 0.0}));
  }
  const double w = std::sqrt((k_a + k_b) / mass);
  const double xi = a1 * k_a / (2.0 * mass * w);
  ExplicitSettings settings;
  settings.time_step = 0.02 / w;
  ExplicitAnalysis analysis(model, model::DofMap::build(model, 3), settings);
  DampingSpec damping;
  damping.stiffness_factor = a1;
  damping.include_in_stiffness_damping = {true, false};
  analysis.set_damping(damping);
  auto nodes = model::initial_configuration(model);
  nodes[1].position.x() += 1.0;
  analysis.set_initial_state(nodes, Eigen::VectorXd::Zero(model.dof_count()));
  // the energy after 5 periods against the exact damped free vibration
  const double periods = 5.0;
  ASSERT_TRUE(analysis.run_to(periods * 2.0 * kPi / w).completed);
  const double energy = analysis.energy().kinetic + analysis.energy().stored;
  const auto exact_energy = [&](double damping_ratio) {
    ExactOscillator exact{mass, 2.0 * damping_ratio * mass * w, k_a + k_b, 1.0, 0.0};
    exact.advance(0.0, 0.0, analysis.time());
    return 0.5 * (k_a + k_b) * exact.u * exact.u + 0.5 * mass * exact.v * exact.v;
  };
  const double expected = exact_energy(xi);
  EXPECT_NEAR(energy, expected, 2e-3 * expected);
  // with the damping of both springs (xi 4/3 as large) it would be clearly less
  EXPECT_GT(std::abs(energy - exact_energy(4.0 / 3.0 * xi)), 0.2 * expected);
  EXPECT_NEAR(analysis.energy().absolute_error(), 0.0, 1e-3 * 0.5 * (k_a + k_b));
}

// --- failures -----------------------------------------------------------------------------

/// A linear spring in ux that refuses any state beyond `limit` (a stand-in for an element
/// whose local iteration fails).
class BreakingSpring final : public element::Element {
public:
  BreakingSpring(std::array<int, 2> nodes, double stiffness, double limit)
      : nodes_(nodes), stiffness_(stiffness), limit_(limit) {}
  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override {
    const double elongation = configuration[1].position.x() - configuration[0].position.x();
    if (std::abs(elongation) > limit_) {
      failure = "breaking spring: elongation beyond its limit";
      return false;
    }
    force = Eigen::VectorXd::Zero(12);
    tangent = Eigen::MatrixXd::Zero(12, 12);
    force[0] = -stiffness_ * elongation;
    force[6] = stiffness_ * elongation;
    tangent(0, 0) = tangent(6, 6) = stiffness_;
    tangent(0, 6) = tangent(6, 0) = -stiffness_;
    energy_ = 0.5 * stiffness_ * elongation * elongation;
    return true;
  }
  void commit() override {}
  void revert_to_committed() override {}
  element::ElementEnergy energy() const override { return {energy_, 0.0}; }
  void copy_state_from(const Element& other) override { element::copy_element_value(*this, other); }

private:
  std::array<int, 2> nodes_;
  double stiffness_, limit_;
  double energy_ = 0.0;
};

/// A spring in ux that stiffens beyond a gap (contact closing): k1 for |u| <= gap, then k2.
class StiffeningSpring final : public element::Element {
public:
  StiffeningSpring(std::array<int, 2> nodes, double soft, double stiff, double gap)
      : nodes_(nodes), soft_(soft), stiff_(stiff), gap_(gap) {}
  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string&) override {
    const double u = configuration[1].position.x() - configuration[0].position.x();
    const double beyond = std::max(std::abs(u) - gap_, 0.0);
    const double magnitude = soft_ * std::min(std::abs(u), gap_) + stiff_ * beyond;
    const double f = std::copysign(magnitude, u);
    const double k = beyond > 0.0 ? stiff_ : soft_;
    force = Eigen::VectorXd::Zero(12);
    tangent = Eigen::MatrixXd::Zero(12, 12);
    force[0] = -f;
    force[6] = f;
    tangent(0, 0) = tangent(6, 6) = k;
    tangent(0, 6) = tangent(6, 0) = -k;
    const double within = std::min(std::abs(u), gap_);
    energy_ =
        0.5 * soft_ * within * within + soft_ * gap_ * beyond + 0.5 * stiff_ * beyond * beyond;
    return true;
  }
  void commit() override {}
  void revert_to_committed() override {}
  element::ElementEnergy energy() const override { return {energy_, 0.0}; }
  void copy_state_from(const Element& other) override { element::copy_element_value(*this, other); }

private:
  std::array<int, 2> nodes_;
  double soft_, stiff_, gap_;
  double energy_ = 0.0;
};

TEST(ExplicitAnalysis, AStiffeningStructureReducesTheAutomaticStep) {
  // w = 10 rad/s inside the gap, 30 rad/s beyond it. With safety 0.5 the automatic step is
  // 0.5 * 2 / 10 = 0.1 s, unstable once the gap closes (w dt = 3); the stability check
  // retakes the step at 0.5 * 2 / 30.
  const double mass = 1.0, soft = 100.0, stiff = 900.0, gap = 1.0;
  const auto make_model = [&]() {
    auto model = std::make_unique<Model>();
    model->add_node(Vector3::Zero());
    model->add_node(Vector3::Zero());
    model->fix_all(0);
    for (const Dof dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
      model->fix(1, dof);
    model->add_mass(1, {mass, 0.0, 0.0, 0.0, 0.0, 0.0});
    model->add_element(
        std::make_unique<StiffeningSpring>(std::array<int, 2>{0, 1}, soft, stiff, gap));
    return model;
  };
  const double v0 = 20.0;
  // the first peak from energy conservation: 1/2 m v0^2 = 1/2 k1 gap^2 + k1 gap d + 1/2 k2 d^2
  const double kinetic = 0.5 * mass * v0 * v0;
  const double excursion =
      (-soft * gap +
       std::sqrt(soft * gap * soft * gap - 2.0 * stiff * (0.5 * soft * gap * gap - kinetic))) /
      stiff;
  for (const int interval : {0, 1}) {
    auto model = make_model();
    ExplicitSettings settings;
    settings.stability_check_interval = interval;
    settings.stable_step_safety = 0.5;
    ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
    Eigen::VectorXd velocity = Eigen::VectorXd::Zero(model->dof_count());
    velocity[Model::global_dof(1, model::ux)] = v0;
    analysis.set_initial_state(model::initial_configuration(*model), velocity);
    EXPECT_NEAR(analysis.time_step(), 0.5 * 2.0 / 10.0, 1e-12);
    double largest = 0.0;
    ExplicitStepReport report{true, 0, {}};
    while (report.completed && analysis.time() < 3.0 && largest < 1e6) {
      report = analysis.step();
      largest = std::max(largest, std::abs(node_value(analysis.displacement(), 1, model::ux)));
    }
    if (interval == 0) {
      EXPECT_TRUE(largest >= 1e6 || !report.completed); // diverges
      EXPECT_TRUE(analysis.fallbacks().empty());
      continue;
    }
    EXPECT_TRUE(report.completed) << report.failure;
    EXPECT_GE(analysis.time(), 3.0);
    ASSERT_EQ(analysis.fallbacks().size(), 1u);
    EXPECT_NE(analysis.fallbacks()[0].reason.find("stiffness grew"), std::string::npos);
    EXPECT_NEAR(analysis.time_step(), 0.5 * 2.0 / 30.0, 1e-9);
    EXPECT_NEAR(largest, gap + excursion, 0.02 * (gap + excursion));
  }
}

TEST(ExplicitAnalysis, AnElementRefusingAStateStopsTheRunWithItsReason) {
  Model model;
  model.add_node(Vector3::Zero());
  model.add_node(Vector3::Zero());
  model.fix_all(0);
  for (const Dof dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
    model.fix(1, dof);
  model.add_mass(1, {1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  model.add_element(std::make_unique<BreakingSpring>(std::array<int, 2>{0, 1}, 100.0, 2.0));
  ExplicitSettings settings;
  settings.time_step = 0.01; // w dt = 0.1
  ExplicitAnalysis analysis(model, model::DofMap::build(model, 3), settings);
  auto nodes = model::initial_configuration(model);
  Eigen::VectorXd velocity = Eigen::VectorXd::Zero(model.dof_count());
  velocity[Model::global_dof(1, model::ux)] = 30.0; // amplitude v / w = 3 mm > 2 mm
  analysis.set_initial_state(nodes, velocity);
  const ExplicitStepReport report = analysis.run_to(1.0);
  EXPECT_FALSE(report.completed);
  EXPECT_GT(report.steps, 0);
  EXPECT_NE(report.failure.find("beyond its limit"), std::string::npos) << report.failure;
  ASSERT_TRUE(analysis.failure().has_value());
  EXPECT_LT(analysis.time(), 1.0);
  // the committed state is the last accepted one, within the limit
  EXPECT_LE(std::abs(node_value(analysis.displacement(), 1, model::ux)), 2.0);
  EXPECT_TRUE(analysis.acceleration().allFinite());
}

TEST(ExplicitAnalysis, ANonFiniteGroundAccelerationStopsTheRun) {
  auto model = make_sdof(1.0, 100.0);
  ExplicitSettings settings;
  settings.time_step = 0.01;
  ExplicitAnalysis analysis(*model, model::DofMap::build(*model, 3), settings);
  GroundAcceleration record;
  record.dt = 0.01;
  // a sample's neighbour enters its interpolation (times 0 at the sample): the NaN at
  // 0.03 s first shows at 0.02 s, so one step completes
  record.acceleration = {0.0, 100.0, 50.0, std::numeric_limits<double>::quiet_NaN(), 0.0};
  analysis.add_ground_acceleration(record);
  const ExplicitStepReport report = analysis.run_to(0.05);
  EXPECT_FALSE(report.completed);
  EXPECT_EQ(report.steps, 1);
  EXPECT_NE(report.failure.find("not finite"), std::string::npos) << report.failure;
  EXPECT_TRUE(analysis.displacement().allFinite());
  EXPECT_TRUE(analysis.velocity().allFinite());
  EXPECT_NEAR(analysis.time(), 0.01, 1e-15);
}

TEST(ExplicitAnalysis, RefusesACoupledMassAndLateSetUp) {
  // a rigid diaphragm whose slave carries mass: T^T M T couples the master's ux, uy to rz
  Model model;
  const int master = model.add_node(Vector3::Zero());
  const int slave = model.add_node(Vector3(1000.0, 500.0, 0.0));
  for (const int node : {master, slave}) {
    for (const Dof dof : {model::uz, model::rx, model::ry})
      model.fix(node, dof);
  }
  model.add_rigid_diaphragm({master, {slave}});
  model.add_mass(slave, {2.0, 2.0, 0.0, 0.0, 0.0, 0.0});
  ExplicitAnalysis analysis(model, model::DofMap::build(model, 3));
  try {
    analysis.prepare();
    FAIL() << "a coupled mass was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("diaphragm master"), std::string::npos)
        << error.what();
  }

  auto sdof = make_sdof(1.0, 100.0);
  ExplicitAnalysis late(*sdof, model::DofMap::build(*sdof, 3));
  ASSERT_TRUE(late.step().completed);
  EXPECT_THROW(late.set_damping(DampingSpec{}), std::logic_error);
  EXPECT_THROW(late.add_ground_acceleration(GroundAcceleration{}), std::logic_error);
  // modal damping has no explicit form here
  auto other = make_sdof(1.0, 100.0);
  ExplicitAnalysis modal(*other, model::DofMap::build(*other, 3));
  DampingSpec damping;
  damping.modal_ratios = {0.05};
  EXPECT_THROW(modal.set_damping(damping), std::invalid_argument);
}

TEST(ExplicitAnalysis, RecordSubstepDividesTheRecordStep) {
  EXPECT_DOUBLE_EQ(record_substep(0.01, 0.003), 0.0025);  // ceil(3.33) = 4
  EXPECT_DOUBLE_EQ(record_substep(0.01, 0.0025), 0.0025); // exactly 4
  EXPECT_DOUBLE_EQ(record_substep(0.01, 0.02), 0.01);     // the record step itself
  EXPECT_THROW(record_substep(0.0, 0.01), std::invalid_argument);
}

} // namespace
} // namespace brb::analysis
