// SteelDamagePlasticity3D and its collapse to the beam fiber.
#include "brb/material/fiber_condensation.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include "support/finite_difference.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace brb::material {
namespace {

using UniaxialSteel3D = FiberCondensation<SteelDamagePlasticity3D, FiberStressState::uniaxial>;
using ShearSteel3D =
    FiberCondensation<SteelDamagePlasticity3D, FiberStressState::uniaxial_with_shears>;

/// True when the plastic or the damage branch differs between two trial responses.
template <class Response, class State>
bool branch_changes(const Response& a, const Response& b, const State& committed) {
  const auto plastic = [&](const Response& r) {
    return r.state.equivalent_plastic_strain > committed.equivalent_plastic_strain;
  };
  const auto damaging = [&](const Response& r) { return r.state.damage > committed.damage; };
  return plastic(a) != plastic(b) || damaging(a) != damaging(b);
}

TEST(SteelDamagePlasticity3D, ConsistentTangentMatchesFiniteDifferences) {
  // Reference: central finite differences of the Voigt stress (engineering shear strains)
  // at random states reached by random multiaxial histories: elastic, plastic (Prager +
  // two Chaboche + Voce: a non-symmetric tangent), unloading, and damage loading. Gf is
  // chosen so that damage stays well below 1: at d -> 1 the stress (1 - d) sigma_bar is
  // round-off noise and finite differences say nothing.
  const SteelDamagePlasticity3D law(test::damaging_steel(300.0), 40.0);
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int plastic_checked = 0, damage_checked = 0, elastic_checked = 0;
  for (int history = 0; history < 60; ++history) {
    auto state = law.initial_state();
    Vector6 strain = Vector6::Zero();
    const double scale = 0.002 * (1 + history % 12);
    // mostly isochoric strain paths, as in a yielding metal (a large volumetric strain
    // would load the elastic bulk energy, and damage, without bound)
    const auto random_direction = [&] {
      Vector6 direction;
      for (int i = 0; i < 6; ++i)
        direction[i] = unit(random);
      direction.head<3>().array() -= 0.9 * direction.head<3>().mean();
      return direction;
    };
    const Vector6 direction = random_direction();
    for (int step = 0; step < 20; ++step) {
      const Vector6 jitter = random_direction();
      strain += scale / 20.0 * (direction + 0.3 * jitter);
      state = law.evaluate(state, strain).state;
    }
    // the checked step: keep loading (plastic/damage) or reverse (elastic unloading)
    Vector6 step_strain = (history % 3 == 0 ? -1.0 : 1.0) * scale / 20.0 * direction;
    const Vector6 trial_strain = strain + step_strain;
    const auto response = law.evaluate(state, trial_strain);
    const double h = 1e-8;
    bool kink = false;
    for (int j = 0; j < 6 && !kink; ++j) {
      Vector6 plus = trial_strain, minus = trial_strain;
      plus[j] += h;
      minus[j] -= h;
      kink = branch_changes(law.evaluate(state, plus), law.evaluate(state, minus), state);
    }
    if (kink)
      continue;
    const auto stress_of = [&](const Vector6& e) { return law.evaluate(state, e).stress; };
    const Eigen::MatrixXd numeric = test::central_difference_jacobian(stress_of, trial_strain, h);
    EXPECT_LT(test::relative_difference(response.tangent, numeric), 1e-6) << "history " << history;
    const bool plastic = response.state.equivalent_plastic_strain > state.equivalent_plastic_strain;
    const bool damaging = response.state.damage > state.damage;
    EXPECT_LT(response.state.damage, 0.99);
    plastic_checked += plastic;
    damage_checked += damaging;
    elastic_checked += !plastic && !damaging;
  }
  EXPECT_GE(plastic_checked, 10);
  EXPECT_GE(damage_checked, 5);
  EXPECT_GE(elastic_checked, 5);
}

TEST(SteelDamagePlasticity3D, ElasticResponseIsHookesLaw) {
  // Reference: isotropic Hooke's law, sigma_12 = G gamma_12 with G = E / (2 (1 + nu)).
  const SteelParameters steel = test::linear_mixed_steel();
  const SteelDamagePlasticity3D law(steel, 1.0);
  Vector6 strain;
  strain << 2e-4, -1e-4, 5e-5, 1e-4, -2e-4, 3e-4;
  const auto response = law.evaluate(law.initial_state(), strain);
  const double E = steel.youngs_modulus, nu = steel.poissons_ratio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double volumetric = strain.head<3>().sum();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(response.stress[i], lambda * volumetric + 2 * G * strain[i], 1e-9);
    EXPECT_NEAR(response.stress[3 + i], G * strain[3 + i], 1e-9);
  }
}

TEST(FiberCondensation, UniaxialElasticGivesPoissonContraction) {
  // Reference: uniaxial stress, sigma = E eps and eps_22 = eps_33 = -nu eps.
  const SteelParameters steel = test::linear_mixed_steel();
  const UniaxialSteel3D fiber(SteelDamagePlasticity3D(steel, 1.0));
  const auto response = fiber.evaluate(fiber.initial_state(), Eigen::Matrix<double, 1, 1>(1e-3));
  ASSERT_TRUE(response.converged);
  EXPECT_NEAR(response.stress[0], steel.youngs_modulus * 1e-3, 1e-9);
  EXPECT_NEAR(response.tangent(0, 0), steel.youngs_modulus, 1e-6);
  EXPECT_NEAR(response.state.free_strain[0], -steel.poissons_ratio * 1e-3, 1e-15);
  EXPECT_NEAR(response.state.free_strain[1], -steel.poissons_ratio * 1e-3, 1e-15);
}

TEST(FiberCondensation, PureShearYieldsAtVonMisesShearStrength) {
  // Reference: von Mises, a perfectly plastic fiber in pure shear yields at fy / sqrt(3),
  // elastic slope G before.
  SteelParameters steel = test::linear_mixed_steel(0.0, 0.0);
  const ShearSteel3D fiber(SteelDamagePlasticity3D(steel, 1.0));
  const double G = steel.youngs_modulus / (2.0 * (1.0 + steel.poissons_ratio));
  auto state = fiber.initial_state();
  ShearSteel3D::Response response;
  for (int i = 1; i <= 200; ++i) {
    const double gamma = 0.01 * i / 200.0;
    response = fiber.evaluate(state, Eigen::Vector3d(0.0, gamma, 0.0));
    ASSERT_TRUE(response.converged);
    state = response.state;
    if (G * gamma < steel.yield_stress / std::sqrt(3.0)) {
      EXPECT_NEAR(response.stress[1], G * gamma, 1e-9);
    }
  }
  EXPECT_NEAR(response.stress[1], steel.yield_stress / std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(response.stress[0], 0.0, 1e-9); // no axial stress from shear (isochoric flow)
}

TEST(FiberCondensation, CondensedTangentsMatchFiniteDifferences) {
  // Reference: central differences of the condensed stresses (each evaluation re-solves
  // the free strains from the same committed state).
  const SteelParameters steel = test::damaging_steel();
  const UniaxialSteel3D axial(SteelDamagePlasticity3D(steel, 40.0));
  const ShearSteel3D sheared(SteelDamagePlasticity3D(steel, 40.0));
  auto axial_state = axial.initial_state();
  auto shear_state = sheared.initial_state();
  int checked = 0;
  for (int i = 1; i <= 300; ++i) {
    const double strain = 0.03 * std::sin(0.05 * i) + 0.0004 * i;
    const Eigen::Vector3d given(strain, 0.3 * strain * std::cos(0.07 * i), 0.1 * strain);
    const auto axial_response = axial.evaluate(axial_state, Eigen::Matrix<double, 1, 1>(strain));
    const auto shear_response = sheared.evaluate(shear_state, given);
    if (i % 23 == 0) {
      const double h = 1e-8;
      const auto axial_stress = [&](const Eigen::Matrix<double, 1, 1>& e) {
        return Eigen::VectorXd(axial.evaluate(axial_state, e).stress);
      };
      const auto shear_stress = [&](const Eigen::Vector3d& e) {
        return Eigen::VectorXd(sheared.evaluate(shear_state, e).stress);
      };
      const Eigen::Matrix<double, 1, 1> at(strain);
      EXPECT_LT(test::relative_difference(axial_response.tangent,
                                          test::central_difference_jacobian(axial_stress, at, h)),
                1e-6)
          << "step " << i;
      EXPECT_LT(test::relative_difference(shear_response.tangent, test::central_difference_jacobian(
                                                                      shear_stress, given, h)),
                1e-6)
          << "step " << i;
      ++checked;
    }
    axial_state = axial_response.state;
    shear_state = shear_response.state;
  }
  EXPECT_GT(checked, 10);
  EXPECT_GT(axial_state.material.damage, 0.0);
}

TEST(FiberCondensation, CondensedThreeDimensionalLawEqualsClosedFormUniaxial) {
  // Reference: the closed-form uniaxial law is the exact uniaxial collapse of the 3D law
  // (DESIGN.md section 3), so both must agree to round-off: 1e-9 relative (stress against
  // max(|sigma|, fy), tangent against E, damage absolute) on 1,000 random strain histories,
  // with and without damage.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const SteelParameters with_damage = test::damaging_steel(20.0);
  const SteelParameters without_damage = test::chaboche_voce_steel();
  const double yield_strain = with_damage.yield_stress / with_damage.youngs_modulus;
  double worst_stress = 0.0, worst_tangent = 0.0;
  for (int history = 0; history < 1000; ++history) {
    const SteelParameters& steel = history % 2 ? with_damage : without_damage;
    const SteelUniaxial closed_form(steel, 10.0);
    const UniaxialSteel3D condensed(SteelDamagePlasticity3D(steel, 10.0));
    auto closed_state = closed_form.initial_state();
    auto condensed_state = condensed.initial_state();
    double strain = 0.0;
    const double amplitude = yield_strain * (1.0 + 40.0 * std::abs(unit(random)));
    for (int step = 0; step < 40; ++step) {
      strain = std::clamp(strain + 0.3 * amplitude * unit(random), -amplitude, amplitude);
      const auto a = closed_form.evaluate(closed_state, strain);
      const auto b = condensed.evaluate(condensed_state, Eigen::Matrix<double, 1, 1>(strain));
      ASSERT_TRUE(b.converged) << "history " << history << " step " << step;
      worst_stress = std::max(worst_stress, std::abs(a.stress - b.stress[0]) /
                                                std::max(std::abs(a.stress), steel.yield_stress));
      worst_tangent =
          std::max(worst_tangent, std::abs(a.tangent - b.tangent(0, 0)) / steel.youngs_modulus);
      ASSERT_NEAR(a.state.damage, b.state.material.damage, 1e-9);
      closed_state = a.state;
      condensed_state = b.state;
    }
  }
  EXPECT_LT(worst_stress, 1e-9);
  EXPECT_LT(worst_tangent, 1e-9);
}

TEST(FiberCondensation, DamageStartsAtUltimateStressInCollapsedLaw) {
  // Reference: as for the closed form: onset where the uniaxial effective stress = fu.
  SteelParameters steel = test::linear_mixed_steel(20000.0, 0.0);
  steel.damage = SteelDamageParameters{430.0, 60.0};
  const UniaxialSteel3D fiber(SteelDamagePlasticity3D(steel, 50.0));
  const double E = steel.youngs_modulus, H = steel.kinematic_hardening;
  const double onset = steel.yield_stress / E + (430.0 - steel.yield_stress) * (E + H) / (E * H);
  auto state = fiber.initial_state();
  for (double strain = 0.0; strain < 0.99 * onset; strain += 1e-4) {
    state = fiber.evaluate(state, Eigen::Matrix<double, 1, 1>(strain)).state;
  }
  const auto below = fiber.evaluate(state, Eigen::Matrix<double, 1, 1>(onset * (1.0 - 1e-9)));
  const auto above = fiber.evaluate(state, Eigen::Matrix<double, 1, 1>(onset * (1.0 + 1e-9)));
  EXPECT_EQ(below.state.material.damage, 0.0);
  EXPECT_GT(above.state.material.damage, 0.0);
}

} // namespace
} // namespace brb::material
