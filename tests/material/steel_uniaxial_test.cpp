// Closed-form uniaxial steel law (SteelUniaxial) against theory.
#include "brb/material/steel_uniaxial.hpp"

#include "support/finite_difference.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace brb::material {
namespace {

/// Exact solution of 1D rate-independent plasticity with linear kinematic (H_k) and
/// isotropic (H_i) hardening along a monotone strain step: elastic until
/// |sigma - alpha| = fy + H_i p, then d sigma = E H / (E + H) d eps (H = H_k + H_i).
/// Written independently of the return map: it locates the yield point explicitly.
struct ExactLinearHardening {
  double E, fy, H_k, H_i;
  double plastic_strain = 0.0, back_stress = 0.0, p = 0.0, strain = 0.0;

  double step_to(double target) {
    const double direction = target >= strain ? 1.0 : -1.0;
    const double radius = fy + H_i * p;
    const double yield_strain = plastic_strain + (back_stress + direction * radius) / E;
    if (direction * (target - yield_strain) > 0.0) {
      const double plastic = (target - yield_strain) * E / (E + H_k + H_i);
      plastic_strain += plastic;
      back_stress += H_k * plastic;
      p += std::abs(plastic);
    }
    strain = target;
    return E * (strain - plastic_strain);
  }
};

/// Strain points of triangular cycles 0 -> +a_i -> -a_i -> 0, n points per quarter.
std::vector<double> triangular_cycles(const std::vector<double>& amplitudes, int per_quarter) {
  std::vector<double> path{0.0};
  for (const double amplitude : amplitudes) {
    for (const double target : {amplitude, -amplitude, 0.0}) {
      const double start = path.back();
      const int points = target == 0.0 ? per_quarter : 2 * per_quarter;
      for (int i = 1; i <= points; ++i)
        path.push_back(start + (target - start) * i / points);
    }
  }
  return path;
}

void expect_matches_exact(const SteelParameters& steel, const std::vector<double>& path) {
  const SteelUniaxial law(steel, 1.0);
  ExactLinearHardening exact{steel.youngs_modulus, steel.yield_stress, steel.kinematic_hardening,
                             steel.isotropic_hardening};
  auto state = law.initial_state();
  for (std::size_t i = 1; i < path.size(); ++i) {
    const auto response = law.evaluate(state, path[i]);
    state = response.state;
    const double reference = exact.step_to(path[i]);
    ASSERT_NEAR(response.stress, reference, 1e-9 * steel.yield_stress) << "step " << i;
  }
}

TEST(SteelUniaxial, MonotonicLinearHardeningMatchesClosedForm) {
  // Reference: sigma = fy + E H / (E + H) (eps - fy / E), H = H_kin + H_iso.
  const SteelParameters steel = test::linear_mixed_steel();
  const SteelUniaxial law(steel, 1.0);
  const double E = steel.youngs_modulus;
  const double H = steel.kinematic_hardening + steel.isotropic_hardening;
  const double yield_strain = steel.yield_stress / E;
  auto state = law.initial_state();
  for (int i = 1; i <= 500; ++i) {
    const double strain = 0.05 * i / 500.0;
    const auto response = law.evaluate(state, strain);
    state = response.state;
    const bool plastic = strain > yield_strain;
    const double expected =
        plastic ? steel.yield_stress + E * H / (E + H) * (strain - yield_strain) : E * strain;
    ASSERT_NEAR(response.stress, expected, 1e-9 * steel.yield_stress) << "strain " << strain;
    ASSERT_NEAR(response.tangent, plastic ? E * H / (E + H) : E, 1e-9 * E);
  }
}

TEST(SteelUniaxial, CyclicMixedHardeningMatchesExactSolution) {
  // Reference: ExactLinearHardening above (theory of 1D linear hardening plasticity).
  const std::vector<double> amplitudes{0.001, 0.002, 0.005, 0.01, 0.03};
  expect_matches_exact(test::linear_mixed_steel(), triangular_cycles(amplitudes, 40));
  expect_matches_exact(test::linear_mixed_steel(21000.0, 0.0), triangular_cycles(amplitudes, 7));
  expect_matches_exact(test::linear_mixed_steel(0.0, 8000.0), triangular_cycles(amplitudes, 13));
}

TEST(SteelUniaxial, KinematicBauschingerShiftAndIsotropicGrowth) {
  // Reference: with kinematic hardening the elastic range keeps its width 2 fy and moves
  // with the back-stress, so after a tension peak sigma_max reverse yielding starts at
  // sigma_max - 2 fy; with isotropic hardening the range grows symmetrically, so reverse
  // yielding starts at -sigma_max.
  const double peak_strain = 0.02;
  for (const bool kinematic : {true, false}) {
    const SteelParameters steel =
        kinematic ? test::linear_mixed_steel(20000.0, 0.0) : test::linear_mixed_steel(0.0, 20000.0);
    const SteelUniaxial law(steel, 1.0);
    auto state = law.initial_state();
    double strain = 0.0;
    double peak_stress = 0.0;
    while (strain < peak_strain) {
      strain += 1e-5;
      const auto response = law.evaluate(state, strain);
      state = response.state;
      peak_stress = response.stress;
    }
    const double reverse_yield = kinematic ? peak_stress - 2.0 * steel.yield_stress : -peak_stress;
    // Unload elastically to just above the reverse yield stress, then just beyond it.
    const double elastic_limit = strain - (peak_stress - reverse_yield) / steel.youngs_modulus;
    const auto before = law.evaluate(state, elastic_limit + 1e-9);
    EXPECT_DOUBLE_EQ(before.state.equivalent_plastic_strain, state.equivalent_plastic_strain);
    EXPECT_DOUBLE_EQ(before.tangent, steel.youngs_modulus);
    const auto after = law.evaluate(state, elastic_limit - 1e-6);
    EXPECT_GT(after.state.equivalent_plastic_strain, state.equivalent_plastic_strain);
    EXPECT_NEAR(after.stress, reverse_yield, 0.05);
  }
}

TEST(SteelUniaxial, ChabocheVoceSaturatesAtBoundingStress) {
  // Reference: monotonic Armstrong-Frederick + Voce gives
  // sigma = fy + sum C_k/gamma_k (1 - exp(-gamma_k p)) + Q (1 - exp(-b p)), which tends
  // to fy + sum C_k/gamma_k + Q. Backward Euler keeps the exact fixed point alpha = C/gamma,
  // and its transient error is first order, about gamma dp / 2 of each term.
  SteelParameters steel = test::chaboche_voce_steel();
  steel.kinematic_hardening = 0.0;
  steel.isotropic_hardening = 0.0;
  const double saturation = steel.saturation_stress();
  ASSERT_DOUBLE_EQ(saturation, 275.0 + 12000.0 / 120.0 + 3000.0 / 15.0 + 40.0);

  const SteelUniaxial law(steel, 1.0);
  const auto closed_form = [&](double p) {
    double stress =
        steel.yield_stress + steel.voce_saturation * (1.0 - std::exp(-steel.voce_rate * p));
    for (const auto& term : steel.chaboche) {
      stress += term.modulus / term.recall * (1.0 - std::exp(-term.recall * p));
    }
    return stress;
  };
  const auto max_transient_error = [&](double strain_step) {
    auto state = law.initial_state();
    double max_error = 0.0;
    for (double strain = strain_step; strain < 0.1; strain += strain_step) {
      const auto response = law.evaluate(state, strain);
      state = response.state;
      if (state.equivalent_plastic_strain == 0.0)
        continue; // elastic: no closed form needed
      max_error = std::max(
          max_error, std::abs(response.stress - closed_form(state.equivalent_plastic_strain)));
    }
    return max_error;
  };
  const double coarse = max_transient_error(2e-5);
  const double fine = max_transient_error(1e-5);
  EXPECT_LT(fine, 1e-3 * saturation);
  EXPECT_NEAR(coarse / fine, 2.0, 0.2); // first-order convergence to the closed form

  auto state = law.initial_state();
  double stress = 0.0;
  for (double strain = 1e-3; strain <= 2.0; strain += 1e-3) {
    const auto response = law.evaluate(state, strain);
    state = response.state;
    stress = response.stress;
  }
  EXPECT_NEAR(stress, saturation, 1e-9 * saturation);
  // and in compression after reversal, the same bound with the other sign
  for (double strain = 2.0; strain >= -0.5; strain -= 1e-3) {
    const auto response = law.evaluate(state, strain);
    state = response.state;
    stress = response.stress;
  }
  EXPECT_NEAR(stress, -saturation, 1e-6 * saturation);
}

TEST(SteelUniaxial, DamageStartsExactlyAtUltimateEffectiveStress) {
  // Reference: r0 = fu / sqrt(E), tau = |sigma_bar| / sqrt(E): damage starts when the
  // effective stress reaches fu. With linear hardening sigma_bar = fy + E H/(E+H)(eps - eps_y),
  // so the onset strain is eps_y + (fu - fy)(E + H)/(E H).
  SteelParameters steel = test::linear_mixed_steel(20000.0, 0.0);
  steel.damage = SteelDamageParameters{430.0, 60.0};
  const SteelUniaxial law(steel, 50.0);
  const double E = steel.youngs_modulus;
  const double H = steel.kinematic_hardening;
  const double onset = steel.yield_stress / E + (430.0 - steel.yield_stress) * (E + H) / (E * H);
  auto state = law.initial_state();
  for (double strain = 0.0; strain < 0.99 * onset; strain += 1e-4) {
    state = law.evaluate(state, strain).state;
  }
  const auto below = law.evaluate(state, onset * (1.0 - 1e-9));
  const auto above = law.evaluate(state, onset * (1.0 + 1e-9));
  EXPECT_EQ(below.state.damage, 0.0);
  EXPECT_GT(above.state.damage, 0.0);
  EXPECT_NEAR(below.stress, 430.0, 1e-4);
}

TEST(SteelUniaxial, SofteningDissipatesFractureEnergyPerCharacteristicLength) {
  // Reference: Oliver's regularisation. On the damage loading branch psi0 = r^2 / 2, so the
  // energy released by damage, integral psi0 dd, equals integral_{r0}^{inf} r^2/2 G'(r) dr
  // = Gf / lc for any path (BRB_SOURCE_FACTS section 2). Measured here from the stress and
  // damage outputs alone (psi0 = (sigma / (1 - d))^2 / 2E), run until the tail is negligible.
  SteelParameters steel = test::linear_mixed_steel(60000.0, 0.0);
  steel.yield_stress = 275.0;
  const double fracture_energy = 2.0;
  steel.damage = SteelDamageParameters{300.0, fracture_energy};
  for (const double lc : {2.0, 4.0, 8.0}) {
    const SteelUniaxial law(steel, lc);
    auto state = law.initial_state();
    double released = 0.0;
    double previous_energy = 0.0;
    double previous_damage = 0.0;
    for (double strain = 1e-5; state.damage < 1.0 - 1e-7 && strain < 5.0; strain += 1e-5) {
      const auto response = law.evaluate(state, strain);
      state = response.state;
      const double effective = response.stress / (1.0 - state.damage);
      const double energy = 0.5 * effective * effective / steel.youngs_modulus;
      released += 0.5 * (energy + previous_energy) * (state.damage - previous_damage);
      previous_energy = energy;
      previous_damage = state.damage;
    }
    ASSERT_GT(state.damage, 1.0 - 1e-6) << "lc " << lc;
    EXPECT_NEAR(released, fracture_energy / lc, 0.01 * fracture_energy / lc) << "lc " << lc;
    EXPECT_NEAR(state.dissipated.softening, fracture_energy / lc, 0.01 * fracture_energy / lc);
  }
}

TEST(SteelUniaxial, EnergyBookkeepingMatchesExternalWork) {
  // Reference: first law. integral sigma d eps (trapezoid) = free energy + dissipated
  // energy, up to the O(step) error of the time discretisation.
  const SteelParameters steel = test::damaging_steel(8.0);
  const SteelUniaxial law(steel, 5.0);
  auto state = law.initial_state();
  double work = 0.0;
  double previous_stress = 0.0;
  double previous_strain = 0.0;
  for (const double strain : triangular_cycles({0.005, 0.01, 0.02, 0.03, 0.05}, 4000)) {
    const auto response = law.evaluate(state, strain);
    state = response.state;
    work += 0.5 * (response.stress + previous_stress) * (strain - previous_strain);
    previous_stress = response.stress;
    previous_strain = strain;
  }
  ASSERT_GT(state.damage, 0.05);
  const double balance = state.dissipated.total + law.free_energy(state, previous_strain);
  EXPECT_NEAR(balance, work, 2e-3 * work);
}

TEST(SteelUniaxial, ConsistentTangentMatchesFiniteDifferences) {
  // Reference: central finite differences of the stress with the same committed state.
  const SteelParameters steel = test::damaging_steel();
  const SteelUniaxial law(steel, 50.0);
  auto state = law.initial_state();
  std::vector<std::pair<std::string, double>> checks;
  // loading path: elastic, plastic, damage loading, unloading, reverse plastic
  const std::vector<double> path = triangular_cycles({0.002, 0.01, 0.03}, 200);
  int checked = 0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double strain = path[i];
    const auto response = law.evaluate(state, strain);
    if (i % 37 == 0) {
      const double step = 1e-8;
      const double numeric =
          (law.evaluate(state, strain + step).stress - law.evaluate(state, strain - step).stress) /
          (2.0 * step);
      const bool kink =
          (response.state.equivalent_plastic_strain > state.equivalent_plastic_strain) !=
          (law.evaluate(state, strain - step).state.equivalent_plastic_strain >
           state.equivalent_plastic_strain);
      if (!kink) {
        EXPECT_NEAR(response.tangent, numeric, 1e-6 * std::abs(numeric) + 1e-6) << "step " << i;
        ++checked;
      }
    }
    state = response.state;
  }
  EXPECT_GT(checked, 20);
  EXPECT_GT(state.damage, 0.0);
}

} // namespace
} // namespace brb::material
