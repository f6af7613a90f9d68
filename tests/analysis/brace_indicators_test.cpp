// The global-buckling flag's rule (analysis/brace_indicators.hpp), driven with prescribed
// node positions and forces so that each clause is tested on its own: the bow is measured
// from the chord of the outer nodes, less the clearance for a casing, and counts only over a
// step whose shortening goes into the bow (it grows by more than the shortening while the
// brace stiffens by less than half its elastic stiffness).
#include "brb/analysis/brace_indicators.hpp"

#include "support/brace_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

namespace brb::analysis {
namespace {

/// The Girona D3 restrained brace (8 core elements) and a driver of its tracker: every node
/// at its initial place plus a lateral offset along section z given per node.
class GlobalBucklingFlag : public ::testing::Test {
protected:
  GlobalBucklingFlag()
      : brace_(model::build_brace_model(test::girona_d3_restrained(8))),
        tracker_(brace_, brace_.model) {}

  /// Observes the state whose node n sits at its initial place + offset(n) along section z.
  template <class Offset> void observe(const Offset& offset, double deformation, double force) {
    positions_.clear();
    for (int node = 0; node < brace_.model.node_count(); ++node)
      positions_.push_back(brace_.model.coordinates(node) + offset(node) * brace_.axes.col(2));
    tracker_.observe([&](int node) -> const element::Vector3& { return positions_[node]; },
                     deformation, force);
  }

  /// A half-sine bow of the casing with the given amplitude (mm); core and ends stay put.
  void observe_casing_bow(double amplitude, double deformation, double force) {
    const auto& casing = *brace_.casing;
    const double first = brace_.model.coordinates(casing.nodes.front()).x();
    const double last = brace_.model.coordinates(casing.nodes.back()).x();
    observe(
        [&](int node) {
          for (const int casing_node : casing.nodes) {
            if (casing_node == node) {
              const double x = brace_.model.coordinates(node).x();
              return amplitude * std::sin(std::numbers::pi * (x - first) / (last - first));
            }
          }
          return 0.0;
        },
        deformation, force);
  }

  double threshold() const { return 2196.0 / 250.0; } // L_y / 250 of Girona D3
  double gap() const { return brace_.casing->interior_link.gap_z; }
  double dy() const { return brace_.yield_deformation; }
  double py() const { return brace_.yield_force; }

  model::BraceModel brace_;
  BraceIndicatorTracker tracker_;
  std::vector<element::Vector3> positions_;
};

TEST_F(GlobalBucklingFlag, ARigidSidewaysMotionOfTheWholeBraceIsNoBow) {
  // as a brace in a frame whose floors drift: every node, the ends included, 50 mm sideways,
  // while the force falls (rule: offsets from the current chord)
  observe([](int) { return 50.0; }, -0.5 * dy(), -0.5 * py());
  observe([](int) { return 50.0; }, -1.0 * dy(), -0.2 * py());
  EXPECT_FALSE(tracker_.indicators().global_buckling);
}

TEST_F(GlobalBucklingFlag, ACasingShiftedWithinItsGapIsNoBow) {
  // the casing moves sideways by more than L_y / 250 but by less than that plus the gap
  const double shift = threshold() + 0.5 * gap();
  const auto& casing = *brace_.casing;
  const auto offset = [&](int node) {
    for (const int casing_node : casing.nodes) {
      if (casing_node == node)
        return shift;
    }
    return 0.0;
  };
  observe(offset, -0.5 * dy(), -0.5 * py());
  observe(offset, -1.0 * dy(), -0.2 * py());
  EXPECT_FALSE(tracker_.indicators().global_buckling);
}

TEST_F(GlobalBucklingFlag, ABowThatHoldsItsForceIsNoBuckle) {
  // a swing sideways at small load that then holds: the bow appears in one step while the
  // force rises at the elastic stiffness P_y / d_y, and stays while the core yields
  const double bow = gap() + 2.0 * threshold();
  observe_casing_bow(bow, -0.1 * dy(), -0.1 * py());
  for (int k = 2; k <= 30; ++k)
    observe_casing_bow(bow, -0.1 * k * dy(), -std::min(0.1 * k, 1.0 + 0.001 * k) * py());
  EXPECT_FALSE(tracker_.indicators().global_buckling);
  EXPECT_GT(tracker_.indicators().max_casing_lateral_displacement, threshold());
}

TEST_F(GlobalBucklingFlag, AnElasticPlateauBelowTheYieldForceIsABuckle) {
  // the force rises elastically to 0.4 P_y, then stays there while the casing bows
  const double bow = gap() + 2.0 * threshold();
  for (int k = 1; k <= 4; ++k)
    observe_casing_bow(0.1 * k * bow, -0.1 * k * dy(), -0.1 * k * py());
  ASSERT_FALSE(tracker_.indicators().global_buckling); // bow still under the threshold
  observe_casing_bow(bow, -0.5 * dy(), -0.41 * py());
  EXPECT_TRUE(tracker_.indicators().global_buckling);
}

TEST_F(GlobalBucklingFlag, AForceDropWhileTheBowGrowsIsABuckle) {
  // past yield, the bow grows from just over the threshold while the force falls
  const double bow = gap() + 1.1 * threshold();
  observe_casing_bow(0.0, -0.5 * dy(), -0.5 * py());
  observe_casing_bow(bow, -1.0 * dy(), -1.0 * py()); // the bow appears, the force rises
  observe_casing_bow(bow, -2.0 * dy(), -1.1 * py()); // the core yields, the bow stays
  EXPECT_FALSE(tracker_.indicators().global_buckling);
  observe_casing_bow(bow + 3.0 * dy(), -2.5 * dy(), -0.9 * py());
  EXPECT_TRUE(tracker_.indicators().global_buckling);
}

TEST_F(GlobalBucklingFlag, ABowThatStopsGrowingIsNoBuckle) {
  // the core yields (the force barely rises) inside a bowed casing whose bow stays put
  const double bow = gap() + 2.0 * threshold();
  observe_casing_bow(bow, -0.5 * dy(), -0.5 * py());
  for (int k = 1; k <= 20; ++k)
    observe_casing_bow(bow, -(1.0 + 0.1 * k) * dy(), -(1.0 + 0.001 * k) * py());
  EXPECT_FALSE(tracker_.indicators().global_buckling);
}

TEST_F(GlobalBucklingFlag, NoBuckleWhileTheBraceIsStretched) {
  const double bow = gap() + 2.0 * threshold();
  observe_casing_bow(bow, 1.0 * dy(), 1.0 * py());
  observe_casing_bow(bow, 0.5 * dy(), 0.2 * py());
  EXPECT_FALSE(tracker_.indicators().global_buckling);
}

/// Evaluates `element` with each node at its initial place plus `offset(node)` and commits.
template <class Offset>
void strain_element(element::Element& element, const model::Model& model, const Offset& offset) {
  std::vector<element::NodeConfiguration> configuration;
  for (const int node : element.nodes())
    configuration.push_back({model.coordinates(node) + offset(node), element::Matrix3::Identity()});
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(element.evaluate(configuration, force, tangent, failure)) << failure;
  element.commit();
}

/// The indicators after the first casing beam of `spec`'s brace is stretched by 1 %: its fill
/// fibers crack through (tension strain 80 times ft / E, damage near 1) while no station bears.
BraceIndicators indicators_with_the_casing_stretched(const model::BraceSpec& spec) {
  model::BraceModel brace = model::build_brace_model(spec);
  auto& beam = *brace.casing->beams.front();
  const int far_node = beam.nodes()[1];
  const double length =
      (brace.model.coordinates(far_node) - brace.model.coordinates(beam.nodes()[0])).norm();
  strain_element(beam, brace.model, [&](int node) {
    return node == far_node ? element::Vector3(0.01 * length * brace.axes.col(0))
                            : element::Vector3::Zero();
  });
  BraceIndicatorTracker tracker(brace, brace.model);
  tracker.observe(
      [&](int node) -> const element::Vector3& { return brace.model.coordinates(node); }, 0.0, 0.0);
  return tracker.indicators();
}

TEST(CasingFailureFlag, FillCrackedInASteelTubeIsNoCasingFailure) {
  // Reference (the flag's rule, README "element.casing_failure"): in a steel tube, casing
  // failure is the mortar under a station crushed through; the fill's cracking, which
  // max_mortar_damage shows, is not (the tube still holds the core).
  const BraceIndicators indicators =
      indicators_with_the_casing_stretched(test::girona_d3_restrained(8));
  EXPECT_GE(indicators.max_mortar_damage, 0.9);
  EXPECT_LE(indicators.min_fill_residual_strength, kCrushedResidualStrength);
  EXPECT_EQ(indicators.max_bearing_damage, 0.0);
  EXPECT_EQ(indicators.min_bearing_residual_strength, 1.0);
  EXPECT_FALSE(indicators.casing_failure);
}

TEST(CasingFailureFlag, AMortarOnlyCasingCrackedThroughIsACasingFailure) {
  // The same casing without its steel tube (an outline, as the thesis's small BRB): the
  // cracked fill is the casing itself.
  model::BraceSpec spec = test::girona_d3_restrained(8);
  spec.casing->steel_tube = false;
  spec.casing->tube.wall = 0.0;
  const BraceIndicators indicators = indicators_with_the_casing_stretched(spec);
  EXPECT_LE(indicators.min_fill_residual_strength, kCrushedResidualStrength);
  EXPECT_EQ(indicators.min_bearing_residual_strength, 1.0);
  EXPECT_TRUE(indicators.casing_failure);
}

/// The indicators after the core of the Girona D3 brace is pushed sideways (z) into the
/// mortar at its middle station by push(link parameters) (mm), no other node moving.
BraceIndicators indicators_with_the_core_pushed_into_a_station(
    const std::function<double(const element::CasingContactParameters&)>& push) {
  model::BraceModel brace = model::build_brace_model(test::girona_d3_restrained(8));
  const model::CasingModel& casing = *brace.casing;
  const std::size_t station = casing.contacts.size() / 2;
  const int core_node = casing.core_nodes[station];
  const double lateral = push(casing.interior_link);
  strain_element(*casing.contacts[station], brace.model, [&](int node) {
    return node == core_node ? element::Vector3(lateral * brace.axes.col(2))
                             : element::Vector3::Zero();
  });
  BraceIndicatorTracker tracker(brace, brace.model);
  tracker.observe(
      [&](int node) -> const element::Vector3& { return brace.model.coordinates(node); }, 0.0, 0.0);
  return tracker.indicators();
}

TEST(CasingFailureFlag, MortarCrushedUnderAStationIsACasingFailure) {
  // The core pushed sideways into the mortar at a station by the gap plus half the mortar's
  // thickness (bearing strain 0.5, hundreds of times fc / E): the bearing face is crushed.
  const BraceIndicators indicators = indicators_with_the_core_pushed_into_a_station(
      [](const element::CasingContactParameters& link) {
        return link.gap_z + 0.5 * link.bearing_depth_z;
      });
  EXPECT_LE(indicators.min_bearing_residual_strength, kCrushedResidualStrength);
  EXPECT_GE(indicators.max_bearing_damage, 0.9);
  EXPECT_EQ(indicators.max_mortar_damage, indicators.max_bearing_damage);
  EXPECT_TRUE(indicators.casing_failure);
}

TEST(CasingFailureFlag, MortarJustPastItsPeakUnderAStationIsNoCasingFailure) {
  // The core pushed into the mortar at a station to a bearing strain where the face keeps 0.2
  // of fc: residual strength exp(A (1 - r / r0)) = 0.2 (ExponentialSoftening), so
  // r / r0 = 1 - ln(0.2) / A. Its damage 1 - 0.2 r0 / r is already past 0.9 (the old rule's
  // threshold: a face that damaged would have flagged), but the face is still bearing a fifth
  // of its strength, and the flag's rule (residual strength <= 0.1) leaves it unflagged.
  const double target = 0.2;
  double old_rule_damage = 0.0;
  const BraceIndicators indicators = indicators_with_the_core_pushed_into_a_station(
      [&](const element::CasingContactParameters& link) {
        const material::MortarUniaxial face_law(link.mortar, link.bearing_depth_z);
        const double threshold_ratio =
            1.0 - std::log(target) / face_law.softening().softening_parameter();
        old_rule_damage = 1.0 - target / threshold_ratio;
        // uniaxial compression: r / r0 = |strain| / (fc / E)
        const double bearing_strain =
            threshold_ratio * link.mortar.compressive_strength / link.mortar.youngs_modulus;
        return link.gap_z + bearing_strain * link.bearing_depth_z;
      });
  ASSERT_GT(old_rule_damage, 0.9) << "the case the old rule flagged";
  EXPECT_NEAR(indicators.min_bearing_residual_strength, target, 0.02);
  EXPECT_GT(indicators.max_bearing_damage, 0.9);
  EXPECT_FALSE(indicators.casing_failure);
}

} // namespace
} // namespace brb::analysis
