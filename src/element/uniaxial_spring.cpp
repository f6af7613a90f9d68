#include "brb/element/uniaxial_spring.hpp"

#include "brb/element/relative_rotation.hpp"
#include "brb/material/parameter_error.hpp"

#include <cmath>

namespace brb::element {

UniaxialSpring::UniaxialSpring(std::array<int, 2> nodes, const Vector3& position_i,
                               const Vector3& position_j, SpringDofLaws laws, const Matrix3& axes)
    : nodes_(nodes), reference_offset_(position_j - position_i), axes_(axes) {
  if (!axes.allFinite() || (axes.transpose() * axes - Matrix3::Identity()).norm() > 1e-9)
    throw ParameterError("axes", "the spring axes must be orthonormal");
  for (int dof = 0; dof < 6; ++dof) {
    if (!laws[dof])
      continue;
    const SpringDofLaw& law = *laws[dof];
    if (!(law.force_scale > 0.0) || !std::isfinite(law.force_scale) ||
        !(law.deformation_scale > 0.0) || !std::isfinite(law.deformation_scale)) {
      throw ParameterError("dofs", "the force and deformation scales of a spring law must be > 0");
    }
    const UniaxialLaw::State initial = law.law.initial_state();
    channels_.push_back({dof, law, initial, initial});
    has_rotations_ = has_rotations_ || dof >= 3;
  }
  if (channels_.empty())
    throw ParameterError("dofs", "a spring needs a law on at least one DOF (ux ... rz)");
}

bool UniaxialSpring::evaluate(std::span<const NodeConfiguration> configuration,
                              Eigen::VectorXd& force, Eigen::MatrixXd& tangent,
                              std::string& failure) {
  const Vector3 stretch = configuration[1].position - configuration[0].position - reference_offset_;
  deformation_.head<3>() = axes_.transpose() * stretch;
  RelativeRotation rotation;
  if (has_rotations_) {
    rotation = relative_rotation(configuration[0].rotation, configuration[1].rotation);
    if (!rotation.vector.allFinite()) {
      failure = "uniaxial spring: the relative rotation of its nodes is not finite";
      return false;
    }
    deformation_.tail<3>() = axes_.transpose() * rotation.vector;
  } else {
    deformation_.tail<3>().setZero();
  }

  dof_force_.setZero();
  Eigen::Matrix<double, 6, 1> dof_stiffness = Eigen::Matrix<double, 6, 1>::Zero();
  energy_ = {};
  for (Channel& channel : channels_) {
    const SpringDofLaw& law = channel.law;
    const double strain = deformation_[channel.dof] / law.deformation_scale;
    const UniaxialLaw::Response response = law.law.evaluate(channel.committed, strain);
    if (!std::isfinite(response.stress) || !std::isfinite(response.tangent)) {
      failure = "uniaxial spring: its law returned a non-finite force";
      return false;
    }
    channel.trial = response.state;
    dof_force_[channel.dof] = law.force_scale * response.stress;
    dof_stiffness[channel.dof] = law.force_scale * response.tangent / law.deformation_scale;
    const double volume = law.force_scale * law.deformation_scale;
    energy_.stored += volume * law.law.free_energy(channel.trial, strain);
    energy_.dissipated += volume * UniaxialLaw::dissipated_energy(channel.trial);
  }

  force = Eigen::VectorXd::Zero(12);
  tangent = Eigen::MatrixXd::Zero(12, 12);
  const Vector3 spring_force = axes_ * dof_force_.head<3>();
  const Matrix3 translational = axes_ * dof_stiffness.head<3>().asDiagonal() * axes_.transpose();
  force.segment<3>(0) = -spring_force;
  force.segment<3>(6) = spring_force;
  tangent.block<3, 3>(0, 0) = translational;
  tangent.block<3, 3>(0, 6) = -translational;
  tangent.block<3, 3>(6, 0) = -translational;
  tangent.block<3, 3>(6, 6) = translational;
  if (has_rotations_) {
    const Vector3 conjugate_moment = axes_ * dof_force_.tail<3>();
    const Matrix3 rotational = axes_ * dof_stiffness.tail<3>().asDiagonal() * axes_.transpose();
    const RelativeRotationResponse moments =
        relative_rotation_response(rotation, conjugate_moment, rotational);
    force.segment<3>(3) = moments.moment_i;
    force.segment<3>(9) = moments.moment_j;
    tangent.block<3, 3>(3, 3) = moments.tangent.block<3, 3>(0, 0);
    tangent.block<3, 3>(3, 9) = moments.tangent.block<3, 3>(0, 3);
    tangent.block<3, 3>(9, 3) = moments.tangent.block<3, 3>(3, 0);
    tangent.block<3, 3>(9, 9) = moments.tangent.block<3, 3>(3, 3);
  }
  return true;
}

void UniaxialSpring::commit() {
  for (Channel& channel : channels_)
    channel.committed = channel.trial;
}

void UniaxialSpring::revert_to_committed() {
  for (Channel& channel : channels_)
    channel.trial = channel.committed;
}

} // namespace brb::element
