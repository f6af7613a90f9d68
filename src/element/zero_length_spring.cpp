#include "brb/element/zero_length_spring.hpp"

#include "brb/element/rotation.hpp"
#include "brb/material/parameter_error.hpp"

#include <cmath>
#include <numbers>

namespace brb::element {

ZeroLengthSpring::ZeroLengthSpring(std::array<int, 2> nodes, const Vector3& position_i,
                                   const Vector3& position_j, const SpringStiffness& stiffness,
                                   const Matrix3& axes)
    : nodes_(nodes), reference_offset_(position_j - position_i) {
  for (const double value : stiffness) {
    if (!(value >= 0.0) || !std::isfinite(value))
      throw ParameterError("stiffness", "each spring stiffness must be >= 0 and finite");
  }
  if (!axes.allFinite() || (axes.transpose() * axes - Matrix3::Identity()).norm() > 1e-9)
    throw ParameterError("axes", "the spring axes must be orthonormal");
  translational_stiffness_ =
      axes * Vector3(stiffness[0], stiffness[1], stiffness[2]).asDiagonal() * axes.transpose();
  rotational_stiffness_ =
      axes * Vector3(stiffness[3], stiffness[4], stiffness[5]).asDiagonal() * axes.transpose();
}

bool ZeroLengthSpring::evaluate(std::span<const NodeConfiguration> configuration,
                                Eigen::VectorXd& force, Eigen::MatrixXd& tangent,
                                std::string& failure) {
  // translations: stretch s = (x_j - x_i) - (X_j - X_i), f_j = K_u s, f_i = -f_j
  const Vector3 stretch = configuration[1].position - configuration[0].position - reference_offset_;
  const Matrix3& translational = translational_stiffness_;
  spring_force_ = translational * stretch;

  // rotations: theta = log(R_j R_i^T)
  const Matrix3 relative = configuration[1].rotation * configuration[0].rotation.transpose();
  const Vector3 theta = vector_from_rotation(relative);
  if (!theta.allFinite() || theta.norm() >= 0.9 * 2.0 * std::numbers::pi) {
    failure = "zero-length spring: relative rotation out of the range of its logarithm";
    return false;
  }
  const Matrix3& rotational = rotational_stiffness_;
  const Vector3 potential_gradient = rotational * theta; // dV/dtheta
  const Matrix3 jacobian_inverse = inverse_left_jacobian(theta);
  spring_moment_ = jacobian_inverse.transpose() * potential_gradient;
  const Vector3 moment_i = -relative.transpose() * spring_moment_;
  stored_energy_ = 0.5 * stretch.dot(spring_force_) + 0.5 * theta.dot(potential_gradient);

  force = Eigen::VectorXd::Zero(12);
  tangent = Eigen::MatrixXd::Zero(12, 12);
  force.segment<3>(0) = -spring_force_;
  force.segment<3>(3) = moment_i;
  force.segment<3>(6) = spring_force_;
  force.segment<3>(9) = spring_moment_;
  tangent.block<3, 3>(0, 0) = translational;
  tangent.block<3, 3>(0, 6) = -translational;
  tangent.block<3, 3>(6, 0) = -translational;
  tangent.block<3, 3>(6, 6) = translational;

  // d theta / d w_j = J^-1, d theta / d w_i = -J^-1 R_rel
  const Matrix3 dtheta_dwj = jacobian_inverse;
  const Matrix3 dtheta_dwi = -jacobian_inverse * relative;
  // d m_j / d theta = J^-T K_r + d(J^-T m)/d theta at m = K_r theta fixed
  const Matrix3 dmj_dtheta = jacobian_inverse.transpose() * rotational +
                             inverse_left_jacobian_transpose_derivative(theta, potential_gradient);
  const Matrix3 dmj_dwj = dmj_dtheta * dtheta_dwj;
  const Matrix3 dmj_dwi = dmj_dtheta * dtheta_dwi;
  // m_i = -R_rel^T m_j with R_rel^T = R_i R_j^T: a spin w_j turns R_rel^T m by
  // R_rel^T [m]x dw_j, a spin w_i by -[R_rel^T m]x dw_i (m held fixed)
  const Matrix3 dmi_dwj =
      -relative.transpose() * dmj_dwj - relative.transpose() * skew(spring_moment_);
  const Matrix3 dmi_dwi =
      -relative.transpose() * dmj_dwi + skew(relative.transpose() * spring_moment_);
  tangent.block<3, 3>(3, 3) = dmi_dwi;
  tangent.block<3, 3>(3, 9) = dmi_dwj;
  tangent.block<3, 3>(9, 3) = dmj_dwi;
  tangent.block<3, 3>(9, 9) = dmj_dwj;
  return true;
}

} // namespace brb::element
