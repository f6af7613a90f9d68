#include "brb/element/casing_contact.hpp"

#include "brb/material/parameter_error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace brb::element {
namespace {

void require(bool condition, const char* field, const std::string& expected) {
  if (!condition)
    throw ParameterError(field, expected);
}

} // namespace

void CasingContactParameters::validate() const {
  require(gap_y >= 0.0 && std::isfinite(gap_y), "gap_y", "clearance must be >= 0 mm");
  require(gap_z >= 0.0 && std::isfinite(gap_z), "gap_z", "clearance must be >= 0 mm");
  require(bearing_area_y > 0.0, "bearing_area_y", "must be > 0 mm^2");
  require(bearing_area_z > 0.0, "bearing_area_z", "must be > 0 mm^2");
  require(bearing_depth_y > 0.0, "bearing_depth_y", "must be > 0 mm");
  require(bearing_depth_z > 0.0, "bearing_depth_z", "must be > 0 mm");
  require(layer_stiffness >= 0.0, "layer_stiffness", "must be >= 0 N/mm");
  require(friction_coefficient >= 0.0, "friction", "must be >= 0");
  require(tangential_stiffness > 0.0, "tangential_stiffness", "must be > 0 N/mm");
  require((axes.transpose() * axes - Matrix3::Identity()).norm() < 1e-9, "axes",
          "must be orthonormal");
}

CasingContact::CasingContact(std::array<int, 2> nodes, const Vector3& core_position,
                             const Vector3& casing_position,
                             const CasingContactParameters& parameters, bool skip_open_links)
    : nodes_(nodes), initial_offset_(core_position - casing_position), parameters_(parameters),
      bearing_{material::MortarUniaxial((parameters.validate(), parameters.mortar),
                                        parameters.bearing_depth_y),
               material::MortarUniaxial(parameters.mortar, parameters.bearing_depth_z)},
      friction_({1.0, parameters.tangential_stiffness, parameters.friction_coefficient}),
      skip_open_links_(skip_open_links) {
  Eigen::VectorXd unused_force;
  scatter(Vector3::Zero(), open_local_tangent(), unused_force, open_tangent_);
}

Matrix3 CasingContact::open_local_tangent() const {
  // The general path's sums with no face penetrated: 0 + k_layer on y and z, and friction's
  // zero tangent (F6 of penalty_friction.cpp) on the axis.
  Matrix3 local_tangent = Matrix3::Zero();
  local_tangent(1, 1) += parameters_.layer_stiffness;
  local_tangent(2, 2) += parameters_.layer_stiffness;
  return local_tangent;
}

void CasingContact::scatter(const Vector3& local_force, const Matrix3& local_tangent,
                            Eigen::VectorXd& force, Eigen::MatrixXd& tangent) const {
  const Matrix3& axes = parameters_.axes;
  const Vector3 global_force = axes * local_force;
  const Matrix3 global_tangent = axes * local_tangent * axes.transpose();
  force = Eigen::VectorXd::Zero(12);
  tangent = Eigen::MatrixXd::Zero(12, 12);
  force.segment<3>(0) = global_force;
  force.segment<3>(6) = -global_force;
  tangent.block<3, 3>(0, 0) = global_tangent;
  tangent.block<3, 3>(0, 6) = -global_tangent;
  tangent.block<3, 3>(6, 0) = -global_tangent;
  tangent.block<3, 3>(6, 6) = global_tangent;
}

bool CasingContact::evaluate(std::span<const NodeConfiguration> configuration,
                             Eigen::VectorXd& force, Eigen::MatrixXd& tangent,
                             std::string& failure) {
  const Matrix3& axes = parameters_.axes;
  relative_ =
      axes.transpose() * (configuration[0].position - configuration[1].position - initial_offset_);
  trial_ = committed_;
  trial_.bearing_strain.fill(0.0);

  if (skip_open_links_ && !(std::abs(relative_[1]) - parameters_.gap_y > 0.0) &&
      !(std::abs(relative_[2]) - parameters_.gap_z > 0.0)) {
    // Open link: the layer springs only. The state changes as the general path changes it:
    // faces as committed, the friction slip follows the axial motion (F6).
    ++open_evaluations_;
    trial_.friction.slip = Eigen::Vector2d(relative_[0], 0.0);
    Vector3 local_force = Vector3::Zero();
    local_force[1] += parameters_.layer_stiffness * relative_[1];
    local_force[2] += parameters_.layer_stiffness * relative_[2];
    in_contact_ = false;
    link_force_ = local_force;
    force = Eigen::VectorXd::Zero(12);
    const Vector3 global_force = parameters_.axes * local_force;
    force.segment<3>(0) = global_force;
    force.segment<3>(6) = -global_force;
    tangent = open_tangent_;
    return true;
  }

  // Bearing on each face: penetration p = |u| - gap on the side the core moves to; the
  // mortar is compressed at strain -p / depth. Faces not penetrated cost nothing.
  Vector3 local_force = Vector3::Zero(); // resisting force on the core (axis, y, z)
  Matrix3 local_tangent = Matrix3::Zero();
  double normal_force = 0.0;
  Eigen::RowVector3d normal_rate = Eigen::RowVector3d::Zero(); // dN/d(relative)
  in_contact_ = false;
  for (int direction = 1; direction <= 2; ++direction) {
    const double gap = direction == 1 ? parameters_.gap_y : parameters_.gap_z;
    const double area = direction == 1 ? parameters_.bearing_area_y : parameters_.bearing_area_z;
    const double depth = direction == 1 ? parameters_.bearing_depth_y : parameters_.bearing_depth_z;
    const material::MortarUniaxial& bearing = bearing_[direction - 1];
    const double motion = relative_[direction];
    const int face = 2 * (direction - 1) + (motion >= 0.0 ? 0 : 1);
    const double penetration = std::abs(motion) - gap;
    if (penetration > 0.0) {
      const double strain = -penetration / depth;
      const auto response = bearing.evaluate(committed_.faces[face], strain);
      if (!std::isfinite(response.stress)) {
        failure = "casing contact: non-finite bearing stress";
        return false;
      }
      trial_.faces[face] = response.state;
      trial_.bearing_strain[face] = strain;
      const double bearing_force = -area * response.stress; // >= 0, pushes the core back
      const double stiffness = area * response.tangent / depth;
      const double sign = motion >= 0.0 ? 1.0 : -1.0;
      local_force[direction] += sign * bearing_force;
      local_tangent(direction, direction) += stiffness;
      normal_force += bearing_force;
      normal_rate[direction] += sign * stiffness;
      in_contact_ = in_contact_ || bearing_force > 0.0;
    }
    // unbonding layer: always active
    local_force[direction] += parameters_.layer_stiffness * motion;
    local_tangent(direction, direction) += parameters_.layer_stiffness;
  }

  // Coulomb friction along the axis with the total bearing force as normal force. Called
  // with dN/dg = 1 so that the tangent's first column is dT/dN.
  const auto friction = friction_.evaluate_with_normal(committed_.friction, normal_force, 1.0,
                                                       Eigen::Vector2d(relative_[0], 0.0));
  trial_.friction = friction.state;
  local_force[0] = friction.tangential_force[0];
  local_tangent(0, 0) = friction.tangent(1, 1);
  local_tangent.row(0) += friction.tangent(1, 0) * normal_rate;
  link_force_ = local_force;
  scatter(local_force, local_tangent, force, tangent);
  return true;
}

ElementEnergy CasingContact::energy() const {
  ElementEnergy energy;
  const double layer = parameters_.layer_stiffness;
  energy.stored = 0.5 * layer * (relative_[1] * relative_[1] + relative_[2] * relative_[2]);
  for (int face = 0; face < 4; ++face) {
    const int direction = face < 2 ? 0 : 1;
    const double area = direction == 0 ? parameters_.bearing_area_y : parameters_.bearing_area_z;
    const double depth = direction == 0 ? parameters_.bearing_depth_y : parameters_.bearing_depth_z;
    const double volume = area * depth;
    energy.stored +=
        volume * bearing_[direction].free_energy(trial_.faces[face], trial_.bearing_strain[face]);
    energy.dissipated += volume * material::MortarUniaxial::dissipated_energy(trial_.faces[face]);
  }
  // friction: the stick spring's energy is stored, the slip work dissipated
  const double stick = relative_[0] - trial_.friction.slip[0];
  energy.stored += 0.5 * parameters_.tangential_stiffness * stick * stick;
  energy.dissipated += trial_.friction.dissipated_energy;
  return energy;
}

double CasingContact::max_mortar_damage() const {
  double worst = 0.0;
  for (const auto& face : trial_.faces)
    worst = std::max(worst, face.damage);
  return worst;
}

} // namespace brb::element
