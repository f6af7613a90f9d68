// Co-rotational kinematics of a two-node 3D beam (Battini & Pacoste, CMAME 191 (2002),
// with nodal triads updated by spins). The element frame R_r = [r1 r2 r3] follows the
// chord (r1) and the mean of the nodal y directors p = (p_i + p_j)/2, p_k = R_k R_o e2;
// the local deformations, free of rigid-body motion, are
//   u_bar = l - l0,   theta_bar_k = log(R_r^T R_k R_o)   (k = i, j),
// ordered d_l = [u_bar, theta_bar_i (3), theta_bar_j (3)] in the element frame.
// Global variations are d_g = [du_i, dw_i, du_j, dw_j] (translations and spins).
//
// Variations used (all derived here, checked against finite differences in the tests):
//   d u_bar = r1 . (du_j - du_i);  element spin omega = R_r^T dw_r = Omega d_g with
//   omega_3 = r2 . dr1, omega_2 = -r3 . dr1, omega_1 = (r3 . dp - q1 r3 . dr1) / q2,
//   q1 = p . r1, q2 = p . r2; d theta_bar_k = J^-1(theta_bar_k) (R_r^T dw_k - omega).
// The tangent is B^T K_l B plus the geometric terms from the variation of B^T at fixed
// local forces (chord rotation, frame spin, and the derivative of J^-T).
#pragma once

#include "brb/element/element.hpp"

#include <Eigen/Core>

namespace brb::element {

using LocalVector = Eigen::Matrix<double, 7, 1>;
using LocalMatrix = Eigen::Matrix<double, 7, 7>;
using GlobalVector = Eigen::Matrix<double, 12, 1>;
using GlobalMatrix = Eigen::Matrix<double, 12, 12>;

class CorotationalFrame {
public:
  /// Initial node positions and a vector in the local x-z plane (OpenSees' vecxz); the
  /// local y axis is vecxz x x, z = x x y. Throws ParameterError on a zero length or a
  /// vecxz parallel to the axis.
  CorotationalFrame(const Vector3& position_i, const Vector3& position_j, const Vector3& vecxz);

  double initial_length() const { return initial_length_; }
  const Matrix3& initial_frame() const { return initial_frame_; }

  /// Moves the frame to the nodes' current configuration. Returns false when the
  /// element degenerates (zero length, or the mean y director along the chord).
  bool update(const NodeConfiguration& node_i, const NodeConfiguration& node_j);

  /// Current local deformations d_l.
  const LocalVector& local_deformation() const { return local_deformation_; }
  double current_length() const { return length_; }
  const Matrix3& frame() const { return frame_; }

  /// Global internal force B^T f_l and the consistent tangent for local forces f_l and
  /// local tangent K_l (both ordered like d_l).
  void global_response(const LocalVector& local_force, const LocalMatrix& local_tangent,
                       GlobalVector& force, GlobalMatrix& tangent) const;

  /// Checkpoints (io/state_archive.hpp): the current state, which outputs read between steps.
  template <class Archive, class Self>
  requires io::state_of<Self, CorotationalFrame>
  friend void state_fields(Archive& archive, Self& frame) {
    archive(frame.length_, frame.frame_, frame.director_i_, frame.director_j_, frame.mean_director_,
            frame.local_deformation_);
  }

private:
  double initial_length_ = 0.0;
  Matrix3 initial_frame_ = Matrix3::Identity();

  // current state
  double length_ = 0.0;
  Matrix3 frame_ = Matrix3::Identity();
  Vector3 director_i_ = Vector3::Zero(); // p_i
  Vector3 director_j_ = Vector3::Zero(); // p_j
  Vector3 mean_director_ = Vector3::Zero();
  LocalVector local_deformation_ = LocalVector::Zero();
};

} // namespace brb::element
