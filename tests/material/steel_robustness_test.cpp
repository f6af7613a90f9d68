// Stress tests of the steel laws: long random strain histories (10^5 steps, strains up
// to 20 %) must give finite stresses and tangents, damage that never decreases and
// non-negative dissipation in every step (second law).
#include "brb/material/fiber_condensation.hpp"
#include "brb/material/steel_damage_plasticity_3d.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <random>

namespace brb::material {
namespace {

constexpr int kSteps = 100000;
constexpr double kMaxStrain = 0.2;

/// Random walk with random step sizes (from tiny to 10 % strain) and occasional jumps.
class RandomStrainWalk {
public:
  explicit RandomStrainWalk(unsigned seed) : random_(seed) {}
  double next(double current) {
    const double size = std::pow(10.0, -6.0 + 5.0 * uniform_(random_)); // 1e-6 .. 0.1
    const double target = jump_(random_) < 0.01 ? kMaxStrain * (2.0 * uniform_(random_) - 1.0)
                                                : current + size * (2.0 * uniform_(random_) - 1.0);
    return std::clamp(target, -kMaxStrain, kMaxStrain);
  }

private:
  std::mt19937 random_;
  std::uniform_real_distribution<double> uniform_{0.0, 1.0};
  std::uniform_real_distribution<double> jump_{0.0, 1.0};
};

template <class State> void expect_admissible_step(const State& before, const State& after) {
  ASSERT_GE(after.damage, before.damage);
  ASSERT_LE(after.damage, 1.0);
  ASSERT_GE(after.dissipated.total - before.dissipated.total, 0.0);
  ASSERT_GE(after.dissipated.plastic - before.dissipated.plastic, 0.0);
  ASSERT_GE(after.dissipated.softening - before.dissipated.softening, 0.0);
  ASSERT_GE(after.equivalent_plastic_strain, before.equivalent_plastic_strain);
}

TEST(SteelRobustness, ClosedFormUniaxialRandomHistory) {
  for (const double fracture_energy : {5.0, 60.0}) {
    const SteelUniaxial law(test::damaging_steel(fracture_energy), 25.0);
    RandomStrainWalk walk(11);
    auto state = law.initial_state();
    double strain = 0.0;
    for (int step = 0; step < kSteps; ++step) {
      strain = walk.next(strain);
      const auto response = law.evaluate(state, strain);
      ASSERT_TRUE(std::isfinite(response.stress) && std::isfinite(response.tangent)) << step;
      expect_admissible_step(state, response.state);
      state = response.state;
    }
    EXPECT_GT(state.damage, 0.5); // the history did reach fracture
  }
}

TEST(SteelRobustness, CondensedThreeDimensionalRandomHistory) {
  using Fiber = FiberCondensation<SteelDamagePlasticity3D, FiberStressState::uniaxial>;
  const Fiber fiber(SteelDamagePlasticity3D(test::damaging_steel(60.0), 25.0));
  RandomStrainWalk walk(12);
  auto state = fiber.initial_state();
  double strain = 0.0;
  for (int step = 0; step < kSteps; ++step) {
    strain = walk.next(strain);
    const auto response = fiber.evaluate(state, Eigen::Matrix<double, 1, 1>(strain));
    ASSERT_TRUE(response.converged) << step;
    ASSERT_TRUE(response.stress.allFinite() && response.tangent.allFinite()) << step;
    expect_admissible_step(state.material, response.state.material);
    state = response.state;
  }
}

TEST(SteelRobustness, ThreeDimensionalRandomMultiaxialHistory) {
  const SteelDamagePlasticity3D law(test::damaging_steel(60.0), 25.0);
  RandomStrainWalk walk(14);
  auto state = law.initial_state();
  Vector6 strain = Vector6::Zero();
  for (int step = 0; step < kSteps; ++step) {
    for (int i = 0; i < 6; ++i)
      strain[i] = walk.next(strain[i]);
    const auto response = law.evaluate(state, strain);
    ASSERT_TRUE(response.stress.allFinite() && response.tangent.allFinite()) << step;
    expect_admissible_step(state, response.state);
    state = response.state;
  }
}

} // namespace
} // namespace brb::material
