// Core-casing interface: penalty contact with Coulomb friction (BRB_SOURCE_FACTS section 4).
//
// Equations implemented:
//   (F1) N = k_N <-g>,  dN/dg = -k_N in contact (g < 0), 0 when open
//   (F2) trial force T_tr = k_T (u_T - s_committed)
//   (F3) Coulomb condition Phi = |T_tr| - kappa N
//   (F4) stick (Phi <= 0): T = T_tr, dT/du = k_T I, dT/dg = 0
//   (F5) slip (Phi > 0): m = T_tr / |T_tr|, T = kappa N m,
//        s_new = s_committed + Phi / k_T m,
//        dT/du = kappa N k_T / |T_tr| (I - m m^T), dT/dg = kappa dN/dg m
//   (F6) open (N = 0): N = T = 0, zero tangent, s_new = u_T (a new contact starts with T = 0)
//   (F7) dissipated energy += T . (s_new - s_committed) = kappa N Phi / k_T >= 0
#include "brb/material/penalty_friction.hpp"

#include "brb/material/parameter_error.hpp"

#include <cmath>
#include <sstream>
#include <string>

namespace brb::material {
namespace {

void require_positive(double value, const char* field, const char* description) {
  if (!(std::isfinite(value) && value > 0.0)) {
    std::ostringstream message;
    message << description << " " << field << " must be finite and > 0 N/mm, got " << value;
    throw ParameterError(field, message.str());
  }
}

} // namespace

void PenaltyFrictionParameters::validate() const {
  require_positive(normal_stiffness, "k_N", "normal penalty stiffness");
  require_positive(tangential_stiffness, "k_T", "tangential penalty stiffness");
  if (!(std::isfinite(friction_coefficient) && friction_coefficient >= 0.0)) {
    std::ostringstream message;
    message << "friction coefficient kappa must be finite and >= 0, got " << friction_coefficient;
    throw ParameterError("kappa", message.str());
  }
}

PenaltyFriction::PenaltyFriction(const PenaltyFrictionParameters& parameters)
    : parameters_(parameters) {
  parameters_.validate();
}

PenaltyFriction::Response
PenaltyFriction::evaluate(const State& committed, double gap,
                          const Eigen::Vector2d& tangential_displacement) const {
  const bool closed = gap < 0.0;
  const double normal_force = closed ? -parameters_.normal_stiffness * gap : 0.0; // (F1)
  const double normal_force_gap_derivative = closed ? -parameters_.normal_stiffness : 0.0;
  return evaluate_with_normal(committed, normal_force, normal_force_gap_derivative,
                              tangential_displacement);
}

PenaltyFriction::Response
PenaltyFriction::evaluate_with_normal(const State& committed, double normal_force,
                                      double normal_force_gap_derivative,
                                      const Eigen::Vector2d& tangential_displacement) const {
  Response response;
  response.state = committed;
  if (!(normal_force > 0.0)) {
    response.state.slip = tangential_displacement; // (F6)
    return response;
  }

  const double stiffness = parameters_.tangential_stiffness;
  const double friction_limit = parameters_.friction_coefficient * normal_force; // kappa N
  const Eigen::Vector2d trial_force =
      stiffness * (tangential_displacement - committed.slip); // (F2)
  const double trial_magnitude = trial_force.norm();
  const double yield_function = trial_magnitude - friction_limit; // (F3)

  response.in_contact = true;
  response.normal_force = normal_force;
  response.tangent(0, 0) = normal_force_gap_derivative;

  if (yield_function <= 0.0) { // (F4) stick
    response.tangential_force = trial_force;
    response.tangent.bottomRightCorner<2, 2>() = stiffness * Eigen::Matrix2d::Identity();
    return response;
  }

  // (F5) slip: radial return onto the Coulomb cone along the trial direction.
  const Eigen::Vector2d direction = trial_force / trial_magnitude;
  const Eigen::Vector2d slip_increment = yield_function / stiffness * direction;
  response.slipping = true;
  response.tangential_force = friction_limit * direction;
  response.tangent.bottomRightCorner<2, 2>() =
      friction_limit * stiffness / trial_magnitude *
      (Eigen::Matrix2d::Identity() - direction * direction.transpose());
  response.tangent.bottomLeftCorner<2, 1>() =
      parameters_.friction_coefficient * normal_force_gap_derivative * direction;
  response.state.slip = committed.slip + slip_increment;
  response.state.dissipated_energy += response.tangential_force.dot(slip_increment); // (F7)
  return response;
}

} // namespace brb::material
