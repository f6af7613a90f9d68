#include "brb/element/relative_rotation.hpp"

#include "brb/element/rotation.hpp"

namespace brb::element {

RelativeRotation relative_rotation(const Matrix3& rotation_i, const Matrix3& rotation_j) {
  RelativeRotation rotation;
  rotation.relative = rotation_j * rotation_i.transpose();
  rotation.vector = vector_from_rotation(rotation.relative);
  rotation.jacobian_inverse = inverse_left_jacobian(rotation.vector);
  return rotation;
}

RelativeRotationResponse relative_rotation_response(const RelativeRotation& rotation,
                                                    const Vector3& conjugate_moment,
                                                    const Matrix3& conjugate_stiffness) {
  RelativeRotationResponse response;
  const Matrix3& relative = rotation.relative;
  const Matrix3& jacobian_inverse = rotation.jacobian_inverse;
  response.moment_j = jacobian_inverse.transpose() * conjugate_moment;
  response.moment_i = -relative.transpose() * response.moment_j;

  // d theta / d w_j = J^-1, d theta / d w_i = -J^-1 R_rel
  const Matrix3 dtheta_dwj = jacobian_inverse;
  const Matrix3 dtheta_dwi = -jacobian_inverse * relative;
  // d m_j / d theta = J^-T G + d(J^-T g)/d theta at g fixed
  const Matrix3 dmj_dtheta =
      jacobian_inverse.transpose() * conjugate_stiffness +
      inverse_left_jacobian_transpose_derivative(rotation.vector, conjugate_moment);
  const Matrix3 dmj_dwj = dmj_dtheta * dtheta_dwj;
  const Matrix3 dmj_dwi = dmj_dtheta * dtheta_dwi;
  // m_i = -R_rel^T m_j with R_rel^T = R_i R_j^T: a spin w_j turns R_rel^T m by
  // R_rel^T [m]x dw_j, a spin w_i by -[R_rel^T m]x dw_i (m held fixed)
  const Vector3& moment_j = response.moment_j;
  response.tangent.block<3, 3>(0, 0) =
      -relative.transpose() * dmj_dwi + skew(relative.transpose() * moment_j);
  response.tangent.block<3, 3>(0, 3) =
      -relative.transpose() * dmj_dwj - relative.transpose() * skew(moment_j);
  response.tangent.block<3, 3>(3, 0) = dmj_dwi;
  response.tangent.block<3, 3>(3, 3) = dmj_dwj;
  return response;
}

} // namespace brb::element
