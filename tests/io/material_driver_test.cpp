// The material-point driver (brb/analysis/material_driver.hpp). It lives with the io tests
// until tests/CMakeLists.txt globs a tests/analysis directory.
#include "brb/analysis/material_driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace brb::analysis {
namespace {

/// A linear elastic point whose evaluation fails (NaN) when asked to jump more than
/// `largest_increment` from its committed strain: it needs substeps for big increments.
struct ShortSightedPoint {
  struct State {
    double strain = 0.0;
    double damage = 0.0;
  };
  struct Response {
    double stress = 0.0;
    double tangent = 0.0;
    State state;
  };

  double modulus = 1000.0;
  double largest_increment = 0.1;

  State initial_state() const { return {}; }
  Response evaluate(const State& committed, double strain) const {
    if (std::abs(strain - committed.strain) > largest_increment) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      return {nan, nan, committed};
    }
    return {modulus * strain, modulus, State{strain, 0.0}};
  }
};

TEST(MaterialDriver, SubstepsIncrementsThatFail) {
  const ShortSightedPoint point{.modulus = 1000.0, .largest_increment = 0.1};
  // 0 -> 0.05: one step. 0.05 -> 0.3 (0.25): 2 substeps of 0.125 fail, 4 of 0.0625 pass.
  // 0.3 -> 0.35: one step.
  const std::vector<double> strains{0.05, 0.3, 0.35};
  const MaterialPathResult path = drive_strain_path_of(point, strains);
  ASSERT_EQ(path.points.size(), strains.size());
  EXPECT_EQ(path.substepped_increments, 1u);
  EXPECT_EQ(path.most_substeps, 4);
  for (std::size_t i = 0; i < strains.size(); ++i) {
    EXPECT_EQ(path.points[i].strain, strains[i]);
    EXPECT_DOUBLE_EQ(path.points[i].stress, 1000.0 * strains[i]);
  }
}

TEST(MaterialDriver, FailureNamesTheRow) {
  const ShortSightedPoint point{.modulus = 1000.0, .largest_increment = 1e-3};
  // The second increment (1.0) would need 1024 substeps of ~1e-3: allow only 64.
  const std::vector<double> strains{1e-4, 1.0};
  try {
    drive_strain_path_of(point, strains, SubsteppingPolicy{.max_substeps = 64});
    FAIL() << "an impossible increment passed";
  } catch (const MaterialPathFailure& failure) {
    EXPECT_EQ(failure.row(), 1u);
    EXPECT_EQ(failure.strain(), 1.0);
    EXPECT_EQ(failure.substeps(), 64);
    EXPECT_NE(std::string(failure.what()).find("row 2"), std::string::npos) << failure.what();
  }
  EXPECT_NO_THROW(drive_strain_path_of(point, strains, SubsteppingPolicy{.max_substeps = 1024}));
}

TEST(MaterialDriver, RejectsAPolicyWithoutSteps) {
  const ShortSightedPoint point;
  const std::vector<double> strains{0.01};
  EXPECT_THROW(drive_strain_path_of(point, strains, SubsteppingPolicy{.max_substeps = 0}),
               std::invalid_argument);
}

material::SteelParameters s275() {
  material::SteelParameters steel;
  steel.youngs_modulus = 210000.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 275.0;
  steel.kinematic_hardening = 2100.0;
  return steel;
}

/// Strains inside the elastic range of a virgin point: +-0.9 of the yield strain.
std::vector<double> elastic_strains(double yield_strain) {
  std::vector<double> strains;
  for (int k = -9; k <= 9; ++k)
    strains.push_back(0.1 * k * yield_strain);
  return strains;
}

TEST(MaterialDriver, ElasticSteelFollowsHookesLawInBothEvaluations) {
  const auto steel = s275();
  const auto strains = elastic_strains(steel.yield_stress / steel.youngs_modulus);
  const material::SteelUniaxial closed_form(steel, 1.0);
  const CollapsedSteel collapsed{material::SteelDamagePlasticity3D(steel, 1.0)};
  for (const UniaxialMaterialPoint& point :
       {UniaxialMaterialPoint(closed_form), UniaxialMaterialPoint(collapsed)}) {
    const auto path = drive_strain_path(point, strains);
    ASSERT_EQ(path.points.size(), strains.size());
    for (const auto& response : path.points) {
      const double hooke = steel.youngs_modulus * response.strain; // sigma = E eps
      EXPECT_NEAR(response.stress, hooke, 1e-10 * steel.yield_stress);
      EXPECT_NEAR(response.tangent, steel.youngs_modulus, 1e-8 * steel.youngs_modulus);
      EXPECT_EQ(response.damage, 0.0);
    }
  }
}

TEST(MaterialDriver, DamagedSteelReportsDamageInBothEvaluations) {
  auto steel = s275();
  steel.damage = material::SteelDamageParameters{.onset_stress = 300.0, .fracture_energy = 50.0};
  const double lc = 10.0;
  std::vector<double> strains;
  for (int k = 1; k <= 200; ++k)
    strains.push_back(5e-4 * k); // to 10 % strain
  const auto closed_form = drive_strain_path(
      material::SteelUniaxial(steel, lc, material::LongElementRule::reject), strains);
  const auto collapsed = drive_strain_path(CollapsedSteel(material::SteelDamagePlasticity3D(
                                               steel, lc, material::LongElementRule::reject)),
                                           strains);
  // Past fu the point must damage; the two exact evaluations of one law must agree.
  EXPECT_GT(closed_form.points.back().damage, 0.0);
  for (std::size_t i = 0; i < strains.size(); ++i) {
    EXPECT_NEAR(collapsed.points[i].stress, closed_form.points[i].stress, 1e-8 * 300.0) << i;
    EXPECT_NEAR(collapsed.points[i].damage, closed_form.points[i].damage, 1e-9) << i;
  }
}

TEST(MaterialDriver, MortarDamagesOnlyPastItsTensileStrength) {
  material::MortarParameters mortar;
  mortar.youngs_modulus = 17520.0;
  mortar.poissons_ratio = 0.2;
  mortar.compressive_strength = 39.92;
  mortar.tensile_strength = 3.992;
  mortar.fracture_energy = 0.75;
  const double cracking_strain = mortar.tensile_strength / mortar.youngs_modulus;
  const std::vector<double> strains{0.5 * cracking_strain, 0.99 * cracking_strain,
                                    2.0 * cracking_strain};
  for (const UniaxialMaterialPoint& point :
       {UniaxialMaterialPoint(material::MortarUniaxial(mortar, 50.0)),
        UniaxialMaterialPoint(CollapsedMortar(material::MortarDamage3D(mortar, 50.0)))}) {
    const auto path = drive_strain_path(point, strains);
    EXPECT_NEAR(path.points[0].stress, mortar.youngs_modulus * strains[0], 1e-10);
    EXPECT_EQ(path.points[1].damage, 0.0);
    EXPECT_GT(path.points[2].damage, 0.0);
    EXPECT_LT(path.points[2].stress, mortar.tensile_strength);
  }
}

} // namespace
} // namespace brb::analysis
