// Moments of a rotational link between two nodal triads (zero-length springs). The relative
// rotation vector theta = log(R_j R_i^T) (global components) is the link's deformation; a
// moment g conjugate to it (g = dV/d theta for an elastic law, the law's moment otherwise)
// acts on the nodes, under spins R <- exp([dw]x) R (element.hpp), as
//   d theta = J^-1(theta) (dw_j - R_rel dw_i),  R_rel = R_j R_i^T   (rotation.hpp),
//   m_j = J^-T g,  m_i = -R_rel^T m_j,
// and the tangent differentiates both exactly (non-symmetric once theta is finite: spins are
// not a parametrisation). The derivation is ZeroLengthSpring's (zero_length_spring.hpp).
#pragma once

#include "brb/element/element.hpp"

namespace brb::element {

struct RelativeRotation {
  Matrix3 relative = Matrix3::Identity();         ///< R_rel = R_j R_i^T
  Vector3 vector = Vector3::Zero();               ///< theta = log(R_rel), |theta| <= pi
  Matrix3 jacobian_inverse = Matrix3::Identity(); ///< J^-1(theta)
};

RelativeRotation relative_rotation(const Matrix3& rotation_i, const Matrix3& rotation_j);

struct RelativeRotationResponse {
  Vector3 moment_i = Vector3::Zero(); ///< N mm, on node i
  Vector3 moment_j = Vector3::Zero(); ///< N mm, on node j
  /// d(m_i, m_j) / d(w_i, w_j)
  Eigen::Matrix<double, 6, 6> tangent = Eigen::Matrix<double, 6, 6>::Zero();
};

/// Nodal moments and tangent of the conjugate moment g(theta) with stiffness dg/d theta.
RelativeRotationResponse relative_rotation_response(const RelativeRotation& rotation,
                                                    const Vector3& conjugate_moment,
                                                    const Matrix3& conjugate_stiffness);

} // namespace brb::element
