// Fallbacks of the transient solver, driven by a test element that refuses states: a linear
// spring along X that cannot evaluate a stretch farther than `limit` from its committed
// stretch (a stand-in for a condensed BRB element whose internal Newton fails on a long
// increment). References: the oscillator's own exact energy balance (average acceleration
// balances exactly whatever the substeps) and the static solution u = P / k.
#include "brb/analysis/transient_analysis.hpp"
#include "brb/model/dof_map.hpp"
#include "support/oscillator_models.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace brb::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

/// Linear spring k along X between nodes {i, j}; refuses a trial stretch farther than
/// `limit` (mm) from the committed one (limit 0: every displaced state).
class IncrementLimitedSpring final : public element::Element {
public:
  IncrementLimitedSpring(std::array<int, 2> nodes, double offset, double stiffness, double limit)
      : nodes_(nodes), offset_(offset), stiffness_(stiffness), limit_(limit) {}

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const element::NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override {
    const double stretch = configuration[1].position.x() - configuration[0].position.x() - offset_;
    if (std::abs(stretch - committed_) > limit_) {
      failure = "test spring refused a stretch increment of " +
                std::to_string(stretch - committed_) + " mm";
      return false;
    }
    trial_ = stretch;
    force = Eigen::VectorXd::Zero(12);
    tangent = Eigen::MatrixXd::Zero(12, 12);
    force[0] = -stiffness_ * stretch;
    force[6] = stiffness_ * stretch;
    tangent(0, 0) = tangent(6, 6) = stiffness_;
    tangent(0, 6) = tangent(6, 0) = -stiffness_;
    return true;
  }
  void commit() override { committed_ = trial_; }
  void revert_to_committed() override { trial_ = committed_; }
  void copy_state_from(const element::Element& other) override {
    element::copy_element_value(*this, other);
  }
  element::ElementEnergy energy() const override {
    return {0.5 * stiffness_ * trial_ * trial_, 0.0};
  }
  double committed_stretch() const { return committed_; }

private:
  std::array<int, 2> nodes_;
  double offset_, stiffness_, limit_;
  double committed_ = 0.0, trial_ = 0.0;
};

constexpr double kMass = 1.0, kPeriod = 0.5;

struct Oscillator {
  model::Model model;
  IncrementLimitedSpring* spring = nullptr;
};

std::unique_ptr<Oscillator> oscillator(double limit) {
  auto result = std::make_unique<Oscillator>();
  const double w = 2.0 * kPi / kPeriod;
  model::Model& model = result->model;
  const int ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(ground);
  const int node = test::add_x_oscillator_node(model, 1000.0, 0.0, kMass);
  result->spring = &model.add_element(std::make_unique<IncrementLimitedSpring>(
      std::array<int, 2>{ground, node}, 1000.0, kMass * w * w, limit));
  return result;
}

GroundAcceleration pulse() {
  GroundAcceleration record;
  record.dt = 0.01;
  for (int i = 0; i <= 20; ++i)
    record.acceleration.push_back(5000.0 * std::sin(kPi * i / 20.0));
  return record;
}

TEST(TransientFallback, RefusedIncrementsAreSubstepped) {
  auto limited = oscillator(0.2);
  TransientAnalysis analysis(limited->model, model::DofMap::build(limited->model, 3));
  analysis.add_ground_acceleration(pulse());
  auto plain = oscillator(1e30);
  TransientAnalysis reference(plain->model, model::DofMap::build(plain->model, 3));
  reference.add_ground_acceleration(pulse());
  const int ux = model::Model::global_dof(1, model::ux);
  const double dt = 0.02;
  double peak = 0.0, reference_peak = 0.0, largest_input = 0.0;
  int substepped = 0;
  for (int n = 0; n < 50; ++n) {
    const TransientStepReport report = analysis.step(dt);
    ASSERT_TRUE(report.converged) << report.failure;
    if (report.substeps > 1)
      ++substepped;
    ASSERT_TRUE(reference.step(dt).converged);
    peak = std::max(peak, std::abs(analysis.displacement()[ux]));
    reference_peak = std::max(reference_peak, std::abs(reference.displacement()[ux]));
    // the balance is exact for average acceleration whatever the substeps
    largest_input = std::max(largest_input, std::abs(analysis.energy().input));
    EXPECT_NEAR(analysis.energy().absolute_error(), 0.0, 1e-9 * largest_input);
  }
  EXPECT_NEAR(analysis.time(), 50 * dt, 1e-12);
  EXPECT_GT(substepped, 0);
  ASSERT_FALSE(analysis.fallbacks().empty());
  EXPECT_NE(analysis.fallbacks().front().what.find("substeps of 1/2"), std::string::npos);
  EXPECT_NE(analysis.fallbacks().front().reason.find("refused"), std::string::npos);
  EXPECT_TRUE(reference.fallbacks().empty());
  ASSERT_GT(reference_peak, 1.0); // the pulse moves the plain oscillator by millimetres
  // smaller (sub)steps than the reference's: the same response within Newmark's error
  EXPECT_NEAR(peak, reference_peak, 0.02 * reference_peak);
}

TEST(TransientFallback, AnElementThatRefusesEverythingFailsCleanly) {
  auto stuck = oscillator(0.0);
  TransientSettings settings;
  settings.max_halvings = 3;
  settings.fallback_iterations = 20;
  TransientAnalysis analysis(stuck->model, model::DofMap::build(stuck->model, 3), settings);
  analysis.add_ground_acceleration(pulse());
  const TransientStepReport report = analysis.step(0.01); // the pulse pushes at once
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.failure.find("every fallback failed"), std::string::npos) << report.failure;
  EXPECT_NE(report.failure.find("refused"), std::string::npos) << report.failure;
  // the committed state is the start
  EXPECT_EQ(analysis.time(), 0.0);
  EXPECT_EQ(analysis.displacement().norm(), 0.0);
  EXPECT_EQ(analysis.velocity().norm(), 0.0);
  EXPECT_EQ(stuck->spring->committed_stretch(), 0.0);
  EXPECT_EQ(analysis.energy().input, 0.0);
  EXPECT_EQ(analysis.energy().kinetic, 0.0);
  // halvings down to the floor (1/8), then the two other algorithms, each with its reason
  const std::vector<FallbackRecord>& fallbacks = analysis.fallbacks();
  ASSERT_EQ(fallbacks.size(), 5u);
  EXPECT_EQ(fallbacks[0].what, "substeps of 1/2 of the step");
  EXPECT_EQ(fallbacks[2].what, "substeps of 1/8 of the step");
  EXPECT_EQ(fallbacks[3].what, "modified Newton (committed tangent)");
  EXPECT_EQ(fallbacks[4].what, "Broyden");
  for (const FallbackRecord& record : fallbacks) {
    EXPECT_EQ(record.time, 0.0);
    EXPECT_NE(record.reason.find("refused"), std::string::npos) << record.reason;
  }
}

TEST(TransientFallback, StaticLoadStepsAreSubsteppedToo) {
  // P = 30 N on k = 157.9 N/mm: u = 0.19 mm, in increments of at most 0.02 mm
  auto limited = oscillator(0.02);
  TransientAnalysis analysis(limited->model, model::DofMap::build(limited->model, 3));
  const double stiffness = kMass * std::pow(2.0 * kPi / kPeriod, 2);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(limited->model.dof_count());
  const int ux = model::Model::global_dof(1, model::ux);
  load[ux] = 30.0;
  const TransientStepReport report = analysis.apply_static_load(load, 2);
  ASSERT_TRUE(report.converged) << report.failure;
  EXPECT_GT(report.substeps, 2);
  EXPECT_NEAR(analysis.displacement()[ux], 30.0 / stiffness, 1e-9);
  EXPECT_NEAR(analysis.energy().static_work, 0.5 * 30.0 * 30.0 / stiffness, 1e-9);
  ASSERT_FALSE(analysis.fallbacks().empty());
  EXPECT_EQ(analysis.fallbacks().front().what.rfind("static load: substeps", 0), 0u);
  // held: a dynamic step at rest changes nothing
  ASSERT_TRUE(analysis.step(0.01).converged);
  EXPECT_NEAR(analysis.displacement()[ux], 30.0 / stiffness, 1e-9);
}

/// A spring f = k s + c s^3 along X whose tangent is not available away from its committed
/// state (it returns a non-finite tangent there, which the assembler rejects): full Newton
/// cannot leave the committed state, modified Newton on the committed tangent can.
class TangentlessSpring final : public element::Element {
public:
  TangentlessSpring(std::array<int, 2> nodes, double offset, double linear, double cubic)
      : nodes_(nodes), offset_(offset), linear_(linear), cubic_(cubic) {}

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const element::NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string&) override {
    const double s = configuration[1].position.x() - configuration[0].position.x() - offset_;
    trial_ = s;
    const double spring_force = linear_ * s + cubic_ * s * s * s;
    const double stiffness =
        s == committed_ ? linear_ + 3.0 * cubic_ * s * s : std::numeric_limits<double>::quiet_NaN();
    force = Eigen::VectorXd::Zero(12);
    tangent = Eigen::MatrixXd::Zero(12, 12);
    force[0] = -spring_force;
    force[6] = spring_force;
    tangent(0, 0) = tangent(6, 6) = stiffness;
    tangent(0, 6) = tangent(6, 0) = -stiffness;
    return true;
  }
  void commit() override { committed_ = trial_; }
  void revert_to_committed() override { trial_ = committed_; }
  void copy_state_from(const element::Element& other) override {
    element::copy_element_value(*this, other);
  }
  element::ElementEnergy energy() const override {
    return {0.5 * linear_ * trial_ * trial_ + 0.25 * cubic_ * std::pow(trial_, 4), 0.0};
  }

private:
  std::array<int, 2> nodes_;
  double offset_, linear_, cubic_;
  double committed_ = 0.0, trial_ = 0.0;
};

TEST(TransientFallback, ModifiedNewtonPassesWhereTheTangentIsMissing) {
  model::Model model;
  const int ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(ground);
  const int node = test::add_x_oscillator_node(model, 1000.0, 0.0, 0.0);
  const double k = 100.0, c = 2.0;
  model.add_element(
      std::make_unique<TangentlessSpring>(std::array<int, 2>{ground, node}, 1000.0, k, c));
  TransientSettings settings;
  settings.max_halvings = 2;
  TransientAnalysis analysis(model, model::DofMap::build(model, 3), settings);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  const int ux = model::Model::global_dof(node, model::ux);
  load[ux] = 2000.0;
  const TransientStepReport report = analysis.apply_static_load(load, 1);
  ASSERT_TRUE(report.converged) << report.failure;
  // k u + c u^3 = P: u = 7.6 mm (Newton on the scalar equation, here)
  double u = 0.0;
  for (int i = 0; i < 50; ++i)
    u -= (k * u + c * u * u * u - 2000.0) / (k + 3.0 * c * u * u);
  EXPECT_NEAR(analysis.displacement()[ux], u, 1e-8 * u);
  bool modified = false;
  for (const FallbackRecord& record : analysis.fallbacks())
    modified = modified || record.what == "static load: modified Newton (committed tangent)";
  EXPECT_TRUE(modified);
}

TEST(TransientFallback, BroydenPassesWhereModifiedNewtonIsTooSlow) {
  // A strongly stiffening spring (tangent at the solution 25 times the committed one):
  // modified Newton with the committed tangent contracts slowly and runs out of its
  // iterations; the secant updates learn the stiffening and converge.
  model::Model model;
  const int ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(ground);
  const int node = test::add_x_oscillator_node(model, 1000.0, 0.0, 0.0);
  const double k = 100.0, c = 2.0, load_value = 20000.0;
  model.add_element(
      std::make_unique<TangentlessSpring>(std::array<int, 2>{ground, node}, 1000.0, k, c));
  TransientSettings settings;
  settings.max_halvings = 0;
  settings.fallback_iterations = 12;
  TransientAnalysis analysis(model, model::DofMap::build(model, 3), settings);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.dof_count());
  const int ux = model::Model::global_dof(node, model::ux);
  load[ux] = load_value;
  const TransientStepReport report = analysis.apply_static_load(load, 1);
  ASSERT_TRUE(report.converged) << report.failure;
  // at the floor (no halvings allowed): Newton failed, then modified Newton, then Broyden
  // converged (nothing recorded after it)
  const std::vector<FallbackRecord>& fallbacks = analysis.fallbacks();
  ASSERT_EQ(fallbacks.size(), 2u);
  EXPECT_EQ(fallbacks[0].what, "static load: modified Newton (committed tangent)");
  EXPECT_NE(fallbacks[0].reason.find("non-finite"), std::string::npos) << fallbacks[0].reason;
  EXPECT_EQ(fallbacks[1].what, "static load: Broyden");
  EXPECT_NE(fallbacks[1].reason.find("did not converge in 12"), std::string::npos)
      << fallbacks[1].reason;
  double u = 0.0;
  for (int i = 0; i < 50; ++i)
    u -= (k * u + c * u * u * u - load_value) / (k + 3.0 * c * u * u);
  EXPECT_NEAR(analysis.displacement()[ux], u, 1e-8 * u);
}

TEST(TransientFallback, InvalidRequestsAreReported) {
  auto plain = oscillator(1e30);
  const model::DofMap map = model::DofMap::build(plain->model, 3);
  TransientSettings settings;
  settings.integrator = TimeIntegrator::hht;
  settings.hht_alpha = -0.5;
  EXPECT_THROW(TransientAnalysis(plain->model, map, settings), std::invalid_argument);
  settings.hht_alpha = 0.1;
  EXPECT_THROW(TransientAnalysis(plain->model, map, settings), std::invalid_argument);

  TransientAnalysis analysis(plain->model, map);
  TransientStepReport report = analysis.apply_static_load(Eigen::VectorXd::Zero(3), 1);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.failure.find("12 DOF"), std::string::npos) << report.failure;
  report = analysis.apply_static_load(Eigen::VectorXd::Zero(12), 0);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.failure.find("load steps"), std::string::npos) << report.failure;
  report = analysis.step(-0.01);
  EXPECT_FALSE(report.converged);
  EXPECT_NE(report.failure.find("time step"), std::string::npos) << report.failure;
  EXPECT_EQ(analysis.time(), 0.0);
}

} // namespace
} // namespace brb::analysis
