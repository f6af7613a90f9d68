// Finite rotations: the exponential and logarithm of SO(3) and the inverse of its left
// Jacobian, used by the co-rotational elements. A rotation vector theta (rad) maps to
// R = exp([theta]x) (Rodrigues); a spin dw updates R <- exp([dw]x) R.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace brb::element {

using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

/// [v]x, the matrix of v x (.)
Matrix3 skew(const Vector3& v);

/// exp([theta]x) by Rodrigues' formula (series near zero).
Matrix3 rotation_from_vector(const Vector3& theta);

/// log of a rotation matrix (angle in [0, pi]), via the quaternion (Shepperd's method).
Vector3 vector_from_rotation(const Matrix3& rotation);

/// Inverse of the left Jacobian: if R = exp(theta) and dR = [dw]x R then
/// d theta = J^-1(theta) dw, J^-1 = I - 1/2 [theta]x + c(t) [theta]x^2,
/// c(t) = 1/t^2 - (1 + cos t) / (2 t sin t), t = |theta| < 2 pi.
Matrix3 inverse_left_jacobian(const Vector3& theta);

/// d/d theta of J^-T(theta) m (3x3), for the geometric stiffness of the local rotations.
Matrix3 inverse_left_jacobian_transpose_derivative(const Vector3& theta, const Vector3& moment);

} // namespace brb::element
