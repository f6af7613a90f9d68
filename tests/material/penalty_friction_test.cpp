// Tests of the core-casing interface law (BRB_SOURCE_FACTS section 4): normal penalty
// N = k_N <-g> and Coulomb friction with a tangential penalty and a stick/slip return map.
// Expected values come from the penalty and Coulomb laws written next to each check.
#include "brb/material/parameter_error.hpp"
#include "brb/material/penalty_friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using brb::ParameterError;
using brb::material::FrictionState;
using brb::material::PenaltyFriction;
using brb::material::PenaltyFrictionParameters;
using Eigen::Vector2d;

constexpr double kNormalStiffness = 1.0e4;     // N/mm
constexpr double kTangentialStiffness = 2.0e3; // N/mm
constexpr double kFriction = 0.1;              // source value (BRB_SOURCE_FACTS section 4)

PenaltyFrictionParameters interface_parameters(double friction = kFriction) {
  PenaltyFrictionParameters parameters;
  parameters.normal_stiffness = kNormalStiffness;
  parameters.tangential_stiffness = kTangentialStiffness;
  parameters.friction_coefficient = friction;
  return parameters;
}

// Penetration 0.01 mm: N = k_N * 0.01 = 100 N, Coulomb limit kappa N = 10 N,
// elastic tangential limit kappa N / k_T = 0.005 mm.
constexpr double kGap = -0.01;
constexpr double kNormalForce = 100.0;
constexpr double kLimit = kFriction * kNormalForce;
constexpr double kStickRange = kLimit / kTangentialStiffness;

TEST(PenaltyFriction, NoForceWhileOpen) {
  const PenaltyFriction law(interface_parameters());
  FrictionState committed;
  committed.slip = Vector2d(0.3, -0.1);
  committed.dissipated_energy = 2.0;
  for (const double gap : {0.2, 1e-9, 0.0}) {
    SCOPED_TRACE(gap);
    const Vector2d displacement(0.7, 0.4);
    const auto response = law.evaluate(committed, gap, displacement);
    EXPECT_FALSE(response.in_contact);
    EXPECT_FALSE(response.slipping);
    EXPECT_EQ(response.normal_force, 0.0);
    EXPECT_EQ(response.tangential_force, Vector2d::Zero());
    EXPECT_EQ(response.tangent, Eigen::Matrix3d::Zero());
    // Slip follows the open surfaces so that a new contact starts with T = 0.
    EXPECT_EQ(response.state.slip, displacement);
    EXPECT_EQ(response.state.dissipated_energy, committed.dissipated_energy);
  }
}

TEST(PenaltyFriction, NormalForceIsPenaltyOnPenetration) {
  const PenaltyFriction law(interface_parameters());
  const auto response = law.evaluate(FrictionState{}, kGap, Vector2d::Zero());
  EXPECT_TRUE(response.in_contact);
  EXPECT_DOUBLE_EQ(response.normal_force, kNormalForce); // N = k_N <-g>
  EXPECT_DOUBLE_EQ(response.tangent(0, 0), -kNormalStiffness);
  EXPECT_EQ(response.tangent(1, 0), 0.0);
  EXPECT_EQ(response.tangent(2, 0), 0.0);
}

TEST(PenaltyFriction, NewContactStartsWithZeroTangentialForce) {
  const PenaltyFriction law(interface_parameters());
  const Vector2d displacement(0.5, 0.25);
  const auto open = law.evaluate(FrictionState{}, 0.1, displacement);
  const auto closed = law.evaluate(open.state, kGap, displacement);
  EXPECT_TRUE(closed.in_contact);
  EXPECT_EQ(closed.tangential_force, Vector2d::Zero());
}

TEST(PenaltyFriction, SticksBelowCoulombLimit) {
  const PenaltyFriction law(interface_parameters());
  const Vector2d displacement(0.002, -0.001); // |k_T u| = 4.47 N < kappa N = 10 N
  const auto response = law.evaluate(FrictionState{}, kGap, displacement);
  EXPECT_FALSE(response.slipping);
  EXPECT_TRUE(response.tangential_force.isApprox(kTangentialStiffness * displacement, 1e-14));
  EXPECT_EQ(response.state.slip, Vector2d::Zero());
  EXPECT_EQ(response.state.dissipated_energy, 0.0);
  Eigen::Matrix3d expected = Eigen::Matrix3d::Zero();
  expected(0, 0) = -kNormalStiffness;
  expected(1, 1) = expected(2, 2) = kTangentialStiffness; // dT/du = k_T I, dT/dg = 0
  EXPECT_TRUE(response.tangent.isApprox(expected, 1e-14));
}

TEST(PenaltyFriction, SlipsAtCoulombLimitAndAccumulatesSlip) {
  const PenaltyFriction law(interface_parameters());
  const auto first = law.evaluate(FrictionState{}, kGap, Vector2d(0.02, 0.0));
  EXPECT_TRUE(first.slipping);
  EXPECT_NEAR(first.tangential_force.norm(), kLimit, 1e-12 * kLimit); // |T| = kappa N
  EXPECT_NEAR(first.tangential_force.x(), kLimit, 1e-12 * kLimit);
  // Elastic part of the displacement is kappa N / k_T, the rest is slip.
  EXPECT_NEAR(first.state.slip.x(), 0.02 - kStickRange, 1e-15);
  EXPECT_EQ(first.state.slip.y(), 0.0);

  const auto second = law.evaluate(first.state, kGap, Vector2d(0.03, 0.0));
  EXPECT_TRUE(second.slipping);
  EXPECT_NEAR(second.tangential_force.x(), kLimit, 1e-12 * kLimit);
  EXPECT_NEAR(second.state.slip.x(), 0.03 - kStickRange, 1e-15);
}

TEST(PenaltyFriction, ReversalSticksThenSlipsBackwards) {
  const PenaltyFriction law(interface_parameters());
  const double peak = 0.02;
  const double slip_at_peak = peak - kStickRange; // 0.015 mm
  FrictionState state = law.evaluate(FrictionState{}, kGap, Vector2d(peak, 0.0)).state;

  // Elastic unloading by k_T from the slip state: T = k_T (u - s).
  for (const double u : {0.018, 0.012}) {
    SCOPED_TRACE(u);
    const auto response = law.evaluate(state, kGap, Vector2d(u, 0.0));
    EXPECT_FALSE(response.slipping);
    EXPECT_NEAR(response.tangential_force.x(), kTangentialStiffness * (u - slip_at_peak),
                1e-12 * kLimit);
    EXPECT_EQ(response.state.slip, state.slip);
  }
  // Past the reversed limit, T = -kappa N and slip runs backwards.
  const double back = 0.005;
  const auto reversed = law.evaluate(state, kGap, Vector2d(back, 0.0));
  EXPECT_TRUE(reversed.slipping);
  EXPECT_NEAR(reversed.tangential_force.x(), -kLimit, 1e-12 * kLimit);
  EXPECT_NEAR(reversed.state.slip.x(), back + kStickRange, 1e-15);
  state = reversed.state;
  // Forward again: stick.
  const auto forward = law.evaluate(state, kGap, Vector2d(back + 0.5 * kStickRange, 0.0));
  EXPECT_FALSE(forward.slipping);
  EXPECT_NEAR(forward.tangential_force.x(), -0.5 * kLimit, 1e-12 * kLimit);
}

TEST(PenaltyFriction, SlipDirectionFollowsTrialDirection) {
  const PenaltyFriction law(interface_parameters());
  FrictionState committed;
  committed.slip = Vector2d(0.01, 0.0);
  for (const double angle : {0.3, 1.9, -2.5}) {
    SCOPED_TRACE(angle);
    const Vector2d direction(std::cos(angle), std::sin(angle));
    const double trial_distance = 0.03; // |T_tr| = 60 N > 10 N
    const Vector2d displacement = committed.slip + trial_distance * direction;
    const auto response = law.evaluate(committed, kGap, displacement);
    EXPECT_TRUE(response.slipping);
    EXPECT_TRUE(response.tangential_force.isApprox(kLimit * direction, 1e-12));
    const Vector2d expected_slip = committed.slip + (trial_distance - kStickRange) * direction;
    EXPECT_TRUE(response.state.slip.isApprox(expected_slip, 1e-12));
  }
}

TEST(PenaltyFriction, ZeroFrictionCoefficientGivesNoTangentialForce) {
  const PenaltyFriction law(interface_parameters(0.0));
  const auto response = law.evaluate(FrictionState{}, kGap, Vector2d(0.02, -0.01));
  EXPECT_TRUE(response.in_contact);
  EXPECT_DOUBLE_EQ(response.normal_force, kNormalForce);
  EXPECT_EQ(response.tangential_force, Vector2d::Zero());
  EXPECT_EQ(response.tangent.bottomRows<2>(), (Eigen::Matrix<double, 2, 3>::Zero()));
  EXPECT_EQ(response.state.dissipated_energy, 0.0);
}

// Consistent tangent against central finite differences on (g, u1, u2), reference: the
// definition of the derivative. The law is piecewise smooth; the points are away from the
// contact and stick/slip boundaries, h = 1e-7 mm gives truncation and round-off << 1e-6.
Eigen::Matrix3d finite_difference_tangent(const PenaltyFriction& law, const FrictionState& state,
                                          double gap, const Vector2d& displacement) {
  const double step = 1e-7;
  Eigen::Matrix3d tangent;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d forward(gap, displacement.x(), displacement.y());
    Eigen::Vector3d backward = forward;
    forward[j] += step;
    backward[j] -= step;
    const auto plus = law.evaluate(state, forward[0], forward.tail<2>());
    const auto minus = law.evaluate(state, backward[0], backward.tail<2>());
    const Eigen::Vector3d force_plus(plus.normal_force, plus.tangential_force.x(),
                                     plus.tangential_force.y());
    const Eigen::Vector3d force_minus(minus.normal_force, minus.tangential_force.x(),
                                      minus.tangential_force.y());
    tangent.col(j) = (force_plus - force_minus) / (2.0 * step);
  }
  return tangent;
}

TEST(PenaltyFriction, ConsistentTangentInStick) {
  const PenaltyFriction law(interface_parameters());
  FrictionState committed;
  committed.slip = Vector2d(0.004, -0.002);
  const Vector2d displacement = committed.slip + Vector2d(0.002, 0.0015); // 5 N < 10 N
  const auto response = law.evaluate(committed, kGap, displacement);
  ASSERT_TRUE(response.in_contact);
  ASSERT_FALSE(response.slipping);
  const Eigen::Matrix3d numerical = finite_difference_tangent(law, committed, kGap, displacement);
  EXPECT_LT((response.tangent - numerical).norm(), 1e-6 * response.tangent.norm());
}

TEST(PenaltyFriction, ConsistentTangentInSlip) {
  const PenaltyFriction law(interface_parameters());
  FrictionState committed;
  committed.slip = Vector2d(0.004, -0.002);
  const Vector2d displacement = committed.slip + Vector2d(0.006, -0.008); // 20 N > 10 N
  const auto response = law.evaluate(committed, kGap, displacement);
  ASSERT_TRUE(response.slipping);
  const Eigen::Matrix3d numerical = finite_difference_tangent(law, committed, kGap, displacement);
  EXPECT_LT((response.tangent - numerical).norm(), 1e-6 * response.tangent.norm());
  // Slip couples the tangential force to the gap: the tangent is non-symmetric.
  EXPECT_NE(response.tangent(1, 0), response.tangent(0, 1));
}

TEST(PenaltyFriction, SteadySlideDissipatesKappaNTimesSlipDistance) {
  // Coulomb: a block sliding a distance s under normal force N dissipates kappa N s.
  const PenaltyFriction law(interface_parameters());
  const double travel = 1.0;
  const int steps = 1000;
  FrictionState state;
  for (int step = 1; step <= steps; ++step) {
    const auto response = law.evaluate(state, kGap, Vector2d(travel * step / steps, 0.0));
    ASSERT_GE(response.state.dissipated_energy, state.dissipated_energy);
    state = response.state;
  }
  const double slip_distance = travel - kStickRange;
  EXPECT_NEAR(state.slip.x(), slip_distance, 1e-12);
  EXPECT_NEAR(state.dissipated_energy, kLimit * slip_distance, 1e-12 * kLimit * slip_distance);
}

TEST(PenaltyFriction, DissipationIsNonNegativeOnRandomHistory) {
  const PenaltyFriction law(interface_parameters());
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> gap(-0.02, 0.01);
  std::uniform_real_distribution<double> move(-0.01, 0.01);
  FrictionState state;
  Vector2d displacement = Vector2d::Zero();
  for (int step = 0; step < 10000; ++step) {
    displacement += Vector2d(move(generator), move(generator));
    const auto response = law.evaluate(state, gap(generator), displacement);
    ASSERT_GE(response.state.dissipated_energy, state.dissipated_energy) << "step " << step;
    // Coulomb admissibility: |T| <= kappa N.
    ASSERT_LE(response.tangential_force.norm(), kFriction * response.normal_force * (1.0 + 1e-12))
        << "step " << step;
    state = response.state;
  }
  EXPECT_GT(state.dissipated_energy, 0.0);
}

TEST(PenaltyFriction, EvaluateWithNormalUsesGivenNormalForce) {
  // Bearing by another law (e.g. mortar): N and dN/dg come from outside.
  const PenaltyFriction law(interface_parameters());
  const double normal_force = 250.0;
  const double normal_slope = -3.0e4;
  const Vector2d displacement(0.0, -0.5); // slip along -y
  const auto response =
      law.evaluate_with_normal(FrictionState{}, normal_force, normal_slope, displacement);
  EXPECT_TRUE(response.slipping);
  EXPECT_EQ(response.normal_force, normal_force);
  EXPECT_EQ(response.tangent(0, 0), normal_slope);
  EXPECT_NEAR(response.tangential_force.y(), -kFriction * normal_force, 1e-12);
  EXPECT_NEAR(response.tangent(2, 0), -kFriction * normal_slope, 1e-12); // kappa dN/dg m
}

std::string rejected_field(const PenaltyFrictionParameters& parameters) {
  try {
    parameters.validate();
  } catch (const ParameterError& error) {
    EXPECT_NE(std::string(error.what()), "");
    return error.field();
  }
  return "(accepted)";
}

TEST(PenaltyFriction, InvalidParametersNameTheirField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    double PenaltyFrictionParameters::*member;
    double value;
    const char* field;
  };
  const std::vector<Case> cases = {
      {&PenaltyFrictionParameters::normal_stiffness, 0.0, "k_N"},
      {&PenaltyFrictionParameters::normal_stiffness, -1.0, "k_N"},
      {&PenaltyFrictionParameters::normal_stiffness, nan, "k_N"},
      {&PenaltyFrictionParameters::normal_stiffness, inf, "k_N"},
      {&PenaltyFrictionParameters::tangential_stiffness, 0.0, "k_T"},
      {&PenaltyFrictionParameters::tangential_stiffness, -1.0, "k_T"},
      {&PenaltyFrictionParameters::tangential_stiffness, nan, "k_T"},
      {&PenaltyFrictionParameters::friction_coefficient, -0.1, "kappa"},
      {&PenaltyFrictionParameters::friction_coefficient, nan, "kappa"},
  };
  for (const auto& c : cases) {
    PenaltyFrictionParameters parameters = interface_parameters();
    parameters.*c.member = c.value;
    SCOPED_TRACE(std::string(c.field) + " = " + std::to_string(c.value));
    EXPECT_EQ(rejected_field(parameters), c.field);
    EXPECT_THROW(PenaltyFriction{parameters}, ParameterError); // the constructor validates
  }
  EXPECT_EQ(rejected_field(interface_parameters(0.0)), "(accepted)"); // kappa = 0 is valid
}

} // namespace
