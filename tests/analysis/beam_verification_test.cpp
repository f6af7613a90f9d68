// Large-displacement verification of the co-rotational beam with the static solver.
#include "brb/analysis/static_analysis.hpp"

#include "support/beam_models.hpp"

#include <boost/numeric/odeint.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::analysis {
namespace {

constexpr double pi = std::numbers::pi;

/// A solid round steel bar with the given E I: E A = E pi d^2/4 with I = pi d^4 / 64,
/// G J = E I / (1 + nu). Slender enough (L/d ~ 50) for the inextensible elastica.
section::ElasticSectionProperties beam_properties(double bending_stiffness) {
  const double youngs = 210000.0;
  const double diameter = std::pow(64.0 * bending_stiffness / (youngs * pi), 0.25);
  return {youngs * pi * diameter * diameter / 4.0, bending_stiffness, bending_stiffness,
          bending_stiffness / 1.3};
}

TEST(BeamVerification, CantileverUnderTipMomentRollsIntoACircle) {
  // Reference: a tip moment M = 2 pi EI / L bends an elastic cantilever into a full circle
  // (constant curvature M/EI = 2 pi / L), so the tip returns to the root.
  const double length = 1000.0, bending = 2.1e9;
  model::Model model;
  test::add_elastic_beam(model, {0, 0, 0}, length, 12, beam_properties(bending));
  model.fix_all(0);
  const int tip = model.node_count() - 1;
  Eigen::VectorXd moment = Eigen::VectorXd::Zero(model.dof_count());
  moment[model::Model::global_dof(tip, model::rz)] = 2.0 * pi * bending / length;
  StaticAnalysis analysis(model);
  analysis.use_load_control(moment);
  for (int step = 1; step <= 20; ++step) {
    ASSERT_TRUE(analysis.step_to(step / 20.0).converged) << "step " << step;
  }
  const element::Vector3 tip_position = analysis.node(tip).position;
  EXPECT_LT(tip_position.norm(), 1e-3 * length);
  // the energy balance of a conservative elastic problem: W = stored
  EXPECT_LT(analysis.energy().relative_error(), 1e-2);
  EXPECT_NEAR(analysis.energy().dissipated, 0.0, 1e-12);
}

/// The elastica of a cantilever under a tip load P normal to its axis, solved
/// independently: theta'' = -(P / EI) cos(theta), theta(0) = 0, theta'(L) = 0, by
/// shooting on theta'(0) with an adaptive Runge-Kutta (Boost.Odeint, Dormand-Prince).
struct ElasticaTip {
  double axial_shortening; ///< L - x_tip
  double deflection;       ///< y_tip
};

ElasticaTip solve_elastica(double load_parameter, double length) {
  using State = std::array<double, 4>; // theta, theta', x, y
  const double k = load_parameter / (length * length);
  const auto integrate = [&](double initial_curvature) {
    State state{0.0, initial_curvature, 0.0, 0.0};
    auto system = [k](const State& s, State& ds, double) {
      ds[0] = s[1];
      ds[1] = -k * std::cos(s[0]);
      ds[2] = std::cos(s[0]);
      ds[3] = std::sin(s[0]);
    };
    boost::numeric::odeint::integrate_adaptive(
        boost::numeric::odeint::make_controlled<boost::numeric::odeint::runge_kutta_dopri5<State>>(
            1e-13, 1e-13),
        system, state, 0.0, length, length / 1000.0);
    return state;
  };
  // theta'(L) is monotone in theta'(0) on [0, k L]: bisection.
  double low = 0.0, high = k * length;
  for (int i = 0; i < 200; ++i) {
    const double middle = 0.5 * (low + high);
    (integrate(middle)[1] > 0.0 ? high : low) = middle;
  }
  const State tip = integrate(0.5 * (low + high));
  return {length - tip[2], tip[3]};
}

TEST(BeamVerification, CantileverUnderTipLoadMatchesTheElastica) {
  // Reference: the exact elastica (independent ODE solution above; it reproduces
  // Mattiasson's (1981) tabulated tip displacements, e.g. PL^2/EI = 1: v/L = 0.30172,
  // u/L = 0.05643). FE tip displacements within 0.5 % with 16 elements.
  const double length = 1000.0, bending = 2.1e9;
  EXPECT_NEAR(solve_elastica(1.0, length).deflection / length, 0.30172, 2e-5);
  EXPECT_NEAR(solve_elastica(1.0, length).axial_shortening / length, 0.05643, 2e-5);

  model::Model model;
  test::add_elastic_beam(model, {0, 0, 0}, length, 16, beam_properties(bending));
  model.fix_all(0);
  const int tip = model.node_count() - 1;
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  load[model::Model::global_dof(tip, model::uy)] = bending / (length * length); // PL^2/EI = 1
  StaticAnalysis analysis(model);
  analysis.use_load_control(load);
  double factor = 0.0;
  for (const double target : {1.0, 2.0, 5.0, 10.0}) {
    while (factor < target - 1e-12) {
      factor = std::min(target, factor + 0.25);
      ASSERT_TRUE(analysis.step_to(factor).converged) << "factor " << factor;
    }
    const ElasticaTip exact = solve_elastica(target, length);
    const double deflection = analysis.displacement(tip, model::uy);
    const double shortening = -analysis.displacement(tip, model::ux);
    EXPECT_NEAR(deflection, exact.deflection, 0.005 * exact.deflection) << "PL^2/EI " << target;
    EXPECT_NEAR(shortening, exact.axial_shortening, 0.005 * exact.axial_shortening)
        << "PL^2/EI " << target;
  }
}

TEST(BeamVerification, PinnedColumnBucklesAtTheEulerLoad) {
  // Reference: Euler, P_E = pi^2 EI / L^2 for a pinned-pinned column. With a small bow
  // imperfection (L/1000) the axial force under growing shortening approaches P_E; the
  // elastica's post-buckling branch is stable and rises only slowly above it.
  const double length = 3000.0, bending = 210000.0 * 2500.0; // 30 x 10 mm bar about its weak axis
  const double euler = pi * pi * bending / (length * length);
  model::Model model;
  const int elements = 8;
  const auto integration =
      element::BeamIntegration::make(element::IntegrationRule::gauss_lobatto, 3);
  const section::ElasticSectionProperties properties{210000.0 * 300.0, bending, 210000.0 * 22500.0,
                                                     80769.0 * 7890.0};
  for (int n = 0; n <= elements; ++n) {
    const double x = length * n / elements;
    model.add_node({x, 0.0, 0.001 * length * std::sin(pi * x / length)}); // bow in z
  }
  for (int e = 0; e < elements; ++e) {
    model.add_element(std::make_unique<test::ElasticBeam>(
        std::array<int, 2>{e, e + 1}, model.coordinates(e), model.coordinates(e + 1),
        element::Vector3(0, 0, 1), integration,
        std::vector(integration.weights.size(), section::ElasticSection(properties))));
  }
  // pinned: translations fixed at the start, lateral ones at the end, twist at the start
  for (const auto dof : {model::ux, model::uy, model::uz, model::rx})
    model.fix(0, dof);
  for (const auto dof : {model::uy, model::uz})
    model.fix(elements, dof);
  StaticAnalysis analysis(model);
  analysis.use_displacement_control(elements, model::ux);
  double peak = 0.0;
  for (int step = 1; step <= 120; ++step) {
    const auto report = analysis.step_to(-0.25 * step); // shortening up to 30 mm = 1 % L
    ASSERT_TRUE(report.converged) << "step " << step << ": " << report.failure;
    peak = std::max(peak, -analysis.control_force());
  }
  EXPECT_NEAR(peak, euler, 0.01 * euler);
  // deep in the post-buckling range the bar has bowed out far beyond its imperfection
  EXPECT_GT(std::abs(analysis.displacement(elements / 2, model::uz)), 100.0);
}

} // namespace
} // namespace brb::analysis
