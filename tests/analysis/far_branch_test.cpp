// The far-branch control of StaticAnalysis on a steep path (NewtonSettings::
// max_correction_ratio, far_ratio_growth): a path the tangent predictor mispredicts at every
// substep by the same ratio is followed in a cut or two, not cut down to the floor.
#include "brb/analysis/static_analysis.hpp"
#include "brb/model/model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

namespace brb::analysis {
namespace {

/// Two springs along x on a free node F and a driven node C: an elastic-perfectly plastic
/// spring from the ground to F (stiffness k_p, yield force f_y, backward-Euler return), and an
/// elastic spring geared to C, energy k_e (u_F - n u_C)^2 / 2. At a committed yielded state
/// with no increment the plastic spring is within its yield force and returns its elastic
/// stiffness, so the tangent predictor moves F by n k_e / (k_p + k_e) of C's motion while the
/// plastic path moves it by n: Newton corrects F by about (n - 0.2) times C's motion at every
/// substep, the steep path of a slipping contact whose committed state gives its stick
/// stiffness.
class GearedPlasticSprings final : public element::Element {
public:
  static constexpr double plastic_stiffness = 1e5; // N/mm
  static constexpr double yield_force = 1000.0;    // N
  static constexpr double geared_stiffness = 1e3;  // N/mm
  static constexpr double gear = 20.0;

  GearedPlasticSprings(int free_node, int driven_node, const model::Model& model)
      : nodes_{free_node, driven_node}, free_origin_(model.coordinates(free_node).x()),
        driven_origin_(model.coordinates(driven_node).x()) {}

  std::span<const int> nodes() const override { return nodes_; }

  bool evaluate(std::span<const element::NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string&) override {
    const double free_motion = configuration[0].position.x() - free_origin_;
    const double driven_motion = configuration[1].position.x() - driven_origin_;
    // return mapping of the plastic spring
    const double trial_force = plastic_stiffness * (free_motion - committed_plastic_);
    double plastic_tangent = plastic_stiffness;
    plastic_force_ = trial_force;
    plastic_ = committed_plastic_;
    // (within round-off of the yield force at a committed yielded state: elastic, so that its
    // tangent mispredicts every substep alike)
    if (std::abs(trial_force) > (1.0 + 1e-12) * yield_force) {
      plastic_force_ = std::copysign(yield_force, trial_force);
      plastic_ = free_motion - plastic_force_ / plastic_stiffness;
      plastic_tangent = 0.0;
    }
    gear_stretch_ = free_motion - gear * driven_motion;
    force = Eigen::VectorXd::Zero(12);
    tangent = Eigen::MatrixXd::Zero(12, 12);
    force[0] = plastic_force_ + geared_stiffness * gear_stretch_;
    force[6] = -gear * geared_stiffness * gear_stretch_;
    tangent(0, 0) = plastic_tangent + geared_stiffness;
    tangent(0, 6) = tangent(6, 0) = -gear * geared_stiffness;
    tangent(6, 6) = gear * gear * geared_stiffness;
    return true;
  }

  void commit() override {
    committed_dissipated_ += yield_force * std::abs(plastic_ - committed_plastic_);
    committed_plastic_ = plastic_;
  }
  void revert_to_committed() override { plastic_ = committed_plastic_; }

  element::ElementEnergy energy() const override {
    element::ElementEnergy energy;
    energy.stored = 0.5 * plastic_force_ * plastic_force_ / plastic_stiffness +
                    0.5 * geared_stiffness * gear_stretch_ * gear_stretch_;
    energy.dissipated =
        committed_dissipated_ + yield_force * std::abs(plastic_ - committed_plastic_);
    return energy;
  }

  void copy_state_from(const element::Element& other) override {
    element::copy_element_value(*this, other);
  }

  double plastic_force() const { return plastic_force_; }

private:
  std::array<int, 2> nodes_;
  double free_origin_, driven_origin_;
  double committed_plastic_ = 0.0, plastic_ = 0.0;
  double committed_dissipated_ = 0.0;
  double plastic_force_ = 0.0, gear_stretch_ = 0.0;
};

struct DrivenPath {
  int far_branch_cuts = 0;
  int substeps = 0;
  double largest_path_error = 0.0; ///< |u_F - exact| over the steps, mm
};

/// Drives C to 0.5 mm in steps of 0.01 mm. The exact path: F moves by n k_e / (k_p + k_e)
/// of C until the plastic spring yields (u_F = f_y / k_p, at u_C = 0.0505 mm), then
/// u_F = n u_C - f_y / k_e (the plastic spring holds f_y, the geared one bears it).
DrivenPath drive(double far_ratio_growth) {
  using Springs = GearedPlasticSprings;
  model::Model model;
  const int free_node = model.add_node({0.0, 0.0, 0.0});
  const int driven_node = model.add_node({100.0, 0.0, 0.0});
  for (const int node : {free_node, driven_node}) {
    for (const auto dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
      model.fix(node, dof);
  }
  const Springs& springs =
      model.add_element(std::make_unique<Springs>(free_node, driven_node, model));
  NewtonSettings settings;
  settings.far_ratio_growth = far_ratio_growth;
  settings.max_halvings = 6;
  StaticAnalysis analysis(model, settings);
  analysis.use_displacement_control(driven_node, model::ux);
  DrivenPath path;
  for (int step = 1; step <= 50; ++step) {
    const double driven = 0.01 * step;
    const StepReport report = analysis.step_to(driven);
    EXPECT_TRUE(report.converged) << "step " << step << ": " << report.failure;
    path.substeps += report.substeps;
    const double elastic = Springs::gear * Springs::geared_stiffness /
                           (Springs::plastic_stiffness + Springs::geared_stiffness) * driven;
    const double exact =
        elastic * Springs::plastic_stiffness <= Springs::yield_force
            ? elastic
            : Springs::gear * driven - Springs::yield_force / Springs::geared_stiffness;
    path.largest_path_error = std::max(
        path.largest_path_error, std::abs(analysis.displacement(free_node, model::ux) - exact));
  }
  EXPECT_NEAR(springs.plastic_force(), Springs::yield_force, 1e-9 * Springs::yield_force);
  path.far_branch_cuts = analysis.far_branch_cuts();
  return path;
}

TEST(FarBranchControl, FollowsAPathTheTangentMispredictsByTheSameRatioAtEverySubstep) {
  // 45 of the 50 steps start from the yielded spring: each lands far (a correction of about
  // 19.8 times the predicted motion, against max_correction_ratio 5) and is cut; its halves
  // land far by the same ratio and are cut once more, and their halves, far by the same ratio
  // at a third depth (not a ratio that doubles as the step halves, as a jump's does), are
  // accepted: three cuts per step.
  const DrivenPath followed = drive(NewtonSettings{}.far_ratio_growth);
  EXPECT_GE(followed.far_branch_cuts, 44 * 3);
  EXPECT_LE(followed.far_branch_cuts, 50 * 3);
  // Without the growth test every such step is cut to the floor of 2^6 substeps: 63 cuts each.
  const DrivenPath floored = drive(0.0);
  EXPECT_GE(floored.far_branch_cuts, 44 * 63);
  EXPECT_GT(floored.substeps, 10 * followed.substeps);
  // Both follow the exact path (a rate-independent law on a monotonic path: no path
  // dependence on the substeps), to Newton's tolerance.
  EXPECT_LT(followed.largest_path_error, 1e-8);
  EXPECT_LT(floored.largest_path_error, 1e-8);
}

} // namespace
} // namespace brb::analysis
