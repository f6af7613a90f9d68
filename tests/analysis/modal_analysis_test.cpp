// Modal analysis against closed forms: the uniform shear building (n equal masses m, storey
// stiffness k, fixed base) has w_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2n + 1))) and shapes
// phi_j(i) ~ sin((2j - 1) pi i / (2n + 1)) (the fixed-free spring-mass chain; e.g. Humar,
// Dynamics of Structures, or by checking the difference equation); effective masses sum to the
// total mass (completeness of the mass-normalised modes). A rigid diaphragm against its hand
// computed rigid-body system. The Rayleigh and modal damping matrices against their defining
// ratios, phi_j^T C phi_j = 2 xi_j w_j.
#include "brb/analysis/modal_analysis.hpp"
#include "brb/analysis/transient_analysis.hpp"
#include "brb/element/zero_length_spring.hpp"
#include "brb/model/dof_map.hpp"
#include "support/oscillator_models.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

double shear_building_frequency(int storeys, double mass, double stiffness, int j) {
  return 2.0 * std::sqrt(stiffness / mass) *
         std::sin((2.0 * j - 1.0) * kPi / (2.0 * (2.0 * storeys + 1.0)));
}

void expect_shear_building_modes(bool split_storeys) {
  const int storeys = 5;
  const double mass = 40.0, stiffness = 8.0e4;
  model::Model model = test::shear_building(storeys, mass, stiffness, split_storeys);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  const std::vector<Mode> modes =
      modal_analysis(analysis.tangent(), analysis.mass(), analysis.dof_map(), storeys + 3);
  ASSERT_EQ(modes.size(), static_cast<std::size_t>(storeys)); // as many as DOF with mass
  double ratio_sum = 0.0;
  for (int j = 1; j <= storeys; ++j) {
    const Mode& mode = modes[j - 1];
    const double expected = shear_building_frequency(storeys, mass, stiffness, j);
    EXPECT_NEAR(mode.circular_frequency, expected, 1e-8 * expected) << "mode " << j;
    EXPECT_NEAR(mode.period, 2.0 * kPi / expected, 1e-8 * 2.0 * kPi / expected);
    EXPECT_NEAR(mode.shape.dot(analysis.mass() * mode.shape), 1.0, 1e-12);
    // shape: floor i (its ux equation) against sin((2j - 1) pi i / (2n + 1)), mass-normalised
    Eigen::VectorXd analytic(storeys), computed(storeys);
    for (int i = 1; i <= storeys; ++i) {
      const int floor_node = split_storeys ? 2 * i - 1 : i;
      analytic[i - 1] = std::sin((2.0 * j - 1.0) * kPi * i / (2.0 * storeys + 1.0));
      computed[i - 1] = mode.shape[analysis.dof_map().independent_equation(
          model::Model::global_dof(floor_node, model::ux))];
    }
    analytic /= std::sqrt(mass * analytic.squaredNorm());
    if (analytic.dot(computed) < 0.0)
      analytic = -analytic;
    EXPECT_LT((computed - analytic).lpNorm<Eigen::Infinity>(),
              1e-8 * analytic.lpNorm<Eigen::Infinity>());
    // participation: Gamma = phi^T M r, r = 1 on every floor
    EXPECT_NEAR(mode.participation.x(), mass * computed.sum(), 1e-9 * mass);
    EXPECT_EQ(mode.participation.y(), 0.0); // no mass along Y or Z
    EXPECT_EQ(mode.effective_mass_ratio.z(), 0.0);
    ratio_sum += mode.effective_mass_ratio.x();
  }
  EXPECT_NEAR(ratio_sum, 1.0, 1e-10);
  EXPECT_GT(modes[0].effective_mass_ratio.x(), 0.8); // the first mode dominates
}

TEST(ModalAnalysis, ShearBuildingMatchesTheClosedForm) {
  expect_shear_building_modes(false);
}

TEST(ModalAnalysis, MasslessEquationsAreCondensedExactly) {
  // every storey as two springs 2k in series through a massless node: same frequencies,
  // the massless nodes' shape components recovered from statics
  expect_shear_building_modes(true);
}

TEST(ModalAnalysis, MechanismAndMasslessModelsAreErrors) {
  model::Model free_floor;
  free_floor.fix_all(free_floor.add_node({0.0, 0.0, 0.0}));
  test::add_x_oscillator_node(free_floor, 0.0, 3000.0, 1.0); // no spring: a mechanism
  const model::DofMap map = model::DofMap::build(free_floor, 3);
  const Eigen::SparseMatrix<double> zero(map.equation_count(), map.equation_count());
  EXPECT_THROW(modal_analysis(zero, map.reduced_mass(free_floor), map, 1), std::runtime_error);

  model::Model massless = test::single_oscillator(0.0, 100.0);
  TransientAnalysis analysis(massless, model::DofMap::build(massless, 3));
  EXPECT_THROW(modal_analysis(analysis.tangent(), analysis.mass(), analysis.dof_map(), 1),
               std::runtime_error);
}

TEST(ModalAnalysis, RigidDiaphragmCarriesTheRotationalInertiaOfItsSlaves) {
  // Master at the origin (no mass), two slaves of mass m at (+a, 0) and (-a, 0), each on
  // ground springs kx, ky; a torsional spring kr on the master. Rigid-body kinematics give
  // M = diag(2m, 2m, 2 m a^2), K = diag(2 kx, 2 ky, 2 ky a^2 + kr) on (ux, uy, rz) of the
  // master, hence w = sqrt(kx/m), sqrt(ky/m), sqrt((2 ky a^2 + kr) / (2 m a^2)).
  const double m = 3.0, a = 2500.0, kx = 1.0e4, ky = 2.5e4, kr = 4.0e11;
  model::Model model;
  const int master = model.add_node({0.0, 0.0, 3000.0});
  for (const model::Dof dof : {model::uz, model::rx, model::ry})
    model.fix(master, dof);
  std::vector<int> slaves;
  for (const double x : {a, -a}) {
    const int slave = model.add_node({x, 0.0, 3000.0});
    for (const model::Dof dof : {model::uz, model::rx, model::ry})
      model.fix(slave, dof);
    model.add_mass(slave, {m, m, m, 0.0, 0.0, 0.0});
    const int ground = model.add_node({x, 0.0, 0.0});
    model.fix_all(ground);
    model.add_element(std::make_unique<element::ZeroLengthSpring>(
        std::array<int, 2>{ground, slave}, model.coordinates(ground), model.coordinates(slave),
        element::SpringStiffness{kx, ky, 0.0, 0.0, 0.0, 0.0}));
    slaves.push_back(slave);
  }
  const int torsion_ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(torsion_ground);
  model.add_element(std::make_unique<element::ZeroLengthSpring>(
      std::array<int, 2>{torsion_ground, master}, model.coordinates(torsion_ground),
      model.coordinates(master), element::SpringStiffness{0.0, 0.0, 0.0, 0.0, 0.0, kr}));
  model.add_rigid_diaphragm({master, slaves});
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  const model::DofMap& map = analysis.dof_map();
  ASSERT_EQ(map.equation_count(), 3);
  const int rz = map.independent_equation(model::Model::global_dof(master, model::rz));
  EXPECT_NEAR(Eigen::MatrixXd(analysis.mass())(rz, rz), 2.0 * m * a * a, 1e-9 * m * a * a);

  const std::vector<Mode> modes = modal_analysis(analysis.tangent(), analysis.mass(), map, 3);
  ASSERT_EQ(modes.size(), 3u);
  std::vector<double> expected{std::sqrt(kx / m), std::sqrt(ky / m),
                               std::sqrt((2.0 * ky * a * a + kr) / (2.0 * m * a * a))};
  std::sort(expected.begin(), expected.end());
  for (int j = 0; j < 3; ++j)
    EXPECT_NEAR(modes[j].circular_frequency, expected[j], 1e-10 * expected[j]) << "mode " << j;
  // the translational modes take all the mass of their direction, the torsional mode none
  double x_sum = 0.0, y_sum = 0.0;
  for (const Mode& mode : modes) {
    x_sum += mode.effective_mass_ratio.x();
    y_sum += mode.effective_mass_ratio.y();
  }
  EXPECT_NEAR(x_sum, 1.0, 1e-10);
  EXPECT_NEAR(y_sum, 1.0, 1e-10);
}

TEST(ModalAnalysis, RayleighCoefficientsReproduceTheTargetRatios) {
  const int storeys = 5;
  const double mass = 40.0, stiffness = 8.0e4, xi = 0.05;
  model::Model model = test::shear_building(storeys, mass, stiffness);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  const std::vector<Mode> modes =
      modal_analysis(analysis.tangent(), analysis.mass(), analysis.dof_map(), storeys);
  const double w1 = modes[0].circular_frequency, w3 = modes[2].circular_frequency;
  const auto [a0, a1] = rayleigh_coefficients(w1, xi, w3, 0.02);
  DampingSpec damping;
  damping.mass_factor = a0;
  damping.stiffness_factor = a1;
  analysis.set_damping(damping);
  const auto ratio = [&](const Mode& mode) {
    return mode.shape.dot(analysis.damping() * mode.shape) / (2.0 * mode.circular_frequency);
  };
  EXPECT_NEAR(ratio(modes[0]), xi, 1e-10);
  EXPECT_NEAR(ratio(modes[2]), 0.02, 1e-10);
  // between the anchors the Rayleigh curve a0 / (2w) + a1 w / 2 holds for every mode
  for (const Mode& mode : modes) {
    const double w = mode.circular_frequency;
    EXPECT_NEAR(ratio(mode), a0 / (2.0 * w) + a1 * w / 2.0, 1e-10);
  }
}

TEST(ModalAnalysis, StiffnessDampingExcludesTheChosenElements) {
  model::Model model = test::shear_building(3, 10.0, 5.0e4);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  DampingSpec damping;
  damping.stiffness_factor = 0.002;
  damping.include_in_stiffness_damping = {true, false, true}; // the second storey left out
  analysis.set_damping(damping);
  // C = a1 K0 of storeys 1 and 3 only: floors are equations 0, 1, 2
  Eigen::Matrix3d expected;
  expected << 5.0e4, 0.0, 0.0, 0.0, 5.0e4, -5.0e4, 0.0, -5.0e4, 5.0e4;
  expected *= 0.002;
  EXPECT_LT((Eigen::MatrixXd(analysis.damping()) - expected).cwiseAbs().maxCoeff(), 1e-12);
  damping.include_in_stiffness_damping = {true};
  EXPECT_THROW(analysis.set_damping(damping), std::invalid_argument);
}

TEST(ModalAnalysis, ModalDampingGivesEachModeItsRatio) {
  const int storeys = 4;
  model::Model model = test::shear_building(storeys, 25.0, 6.0e4);
  TransientAnalysis analysis(model, model::DofMap::build(model, 3));
  DampingSpec damping;
  damping.modal_ratios = {0.02, 0.05}; // the first two modes; the others undamped
  analysis.set_damping(damping);
  const std::vector<Mode> modes =
      modal_analysis(analysis.tangent(), analysis.mass(), analysis.dof_map(), storeys);
  for (int j = 0; j < storeys; ++j) {
    for (int k = 0; k < storeys; ++k) {
      const double entry = modes[j].shape.dot(analysis.damping() * modes[k].shape);
      const double expected =
          j == k && j < 2 ? 2.0 * damping.modal_ratios[j] * modes[j].circular_frequency : 0.0;
      EXPECT_NEAR(entry, expected, 1e-10) << "modes " << j << ", " << k;
    }
  }
}

} // namespace
} // namespace brb::analysis
