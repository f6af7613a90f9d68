#include "brb/element/corotational_frame.hpp"

#include "brb/element/rotation.hpp"
#include "brb/material/parameter_error.hpp"

#include <cmath>

namespace brb::element {
namespace {

using Block = Eigen::Matrix<double, 3, 12>;

/// Selection of the 3 components starting at `offset` of d_g (0: u_i, 3: w_i, 6: u_j, 9: w_j).
Block select(int offset) {
  Block s = Block::Zero();
  s.block<3, 3>(0, offset).setIdentity();
  return s;
}

} // namespace

CorotationalFrame::CorotationalFrame(const Vector3& position_i, const Vector3& position_j,
                                     const Vector3& vecxz) {
  const Vector3 chord = position_j - position_i;
  initial_length_ = chord.norm();
  if (!(initial_length_ > 0.0))
    throw ParameterError("nodes", "beam element of zero length");
  const Vector3 x = chord / initial_length_;
  Vector3 y = vecxz.cross(x);
  if (y.norm() < 1e-9 * vecxz.norm() || !(vecxz.norm() > 0.0)) {
    throw ParameterError("orientation", "the vector in the local x-z plane must not be parallel "
                                        "to the element axis");
  }
  y.normalize();
  initial_frame_.col(0) = x;
  initial_frame_.col(1) = y;
  initial_frame_.col(2) = x.cross(y);
  length_ = initial_length_;
  frame_ = initial_frame_;
}

bool CorotationalFrame::update(const NodeConfiguration& node_i, const NodeConfiguration& node_j) {
  const Vector3 chord = node_j.position - node_i.position;
  length_ = chord.norm();
  if (!(length_ > 0.0))
    return false;
  const Vector3 r1 = chord / length_;
  director_i_ = node_i.rotation * initial_frame_.col(1);
  director_j_ = node_j.rotation * initial_frame_.col(1);
  mean_director_ = 0.5 * (director_i_ + director_j_);
  Vector3 r3 = r1.cross(mean_director_);
  const double r3_norm = r3.norm();
  if (!(r3_norm > 1e-12))
    return false;
  r3 /= r3_norm;
  frame_.col(0) = r1;
  frame_.col(1) = r3.cross(r1);
  frame_.col(2) = r3;
  local_deformation_[0] = length_ - initial_length_;
  local_deformation_.segment<3>(1) =
      vector_from_rotation(frame_.transpose() * node_i.rotation * initial_frame_);
  local_deformation_.segment<3>(4) =
      vector_from_rotation(frame_.transpose() * node_j.rotation * initial_frame_);
  return true;
}

void CorotationalFrame::global_response(const LocalVector& local_force,
                                        const LocalMatrix& local_tangent, GlobalVector& force,
                                        GlobalMatrix& tangent) const {
  const Vector3 r1 = frame_.col(0), r2 = frame_.col(1), r3 = frame_.col(2);
  const Vector3& p = mean_director_;
  const double l = length_;
  const double q1 = p.dot(r1), q2 = p.dot(r2);
  const Block select_ui = select(0), select_wi = select(3), select_uj = select(6),
              select_wj = select(9);

  // Element spin in the element frame: omega = Omega d_g.
  Block omega;
  omega.row(0) << q1 / (l * q2) * r3.transpose(), director_i_.cross(r3).transpose() / (2.0 * q2),
      -q1 / (l * q2) * r3.transpose(), director_j_.cross(r3).transpose() / (2.0 * q2);
  omega.row(1) << r3.transpose() / l, Eigen::RowVector3d::Zero(), -r3.transpose() / l,
      Eigen::RowVector3d::Zero();
  omega.row(2) << -r2.transpose() / l, Eigen::RowVector3d::Zero(), r2.transpose() / l,
      Eigen::RowVector3d::Zero();

  // Spin of each local rotation: d w_bar_k = (R_r^T S_wk - Omega) d_g.
  const Block spin_i = frame_.transpose() * select_wi - omega;
  const Block spin_j = frame_.transpose() * select_wj - omega;
  const Vector3 theta_i = local_deformation_.segment<3>(1);
  const Vector3 theta_j = local_deformation_.segment<3>(4);
  const Matrix3 jacobian_i = inverse_left_jacobian(theta_i);
  const Matrix3 jacobian_j = inverse_left_jacobian(theta_j);

  Eigen::Matrix<double, 7, 12> b;
  b.row(0) << -r1.transpose(), Eigen::RowVector3d::Zero(), r1.transpose(),
      Eigen::RowVector3d::Zero();
  b.middleRows<3>(1) = jacobian_i * spin_i;
  b.middleRows<3>(4) = jacobian_j * spin_j;

  force = b.transpose() * local_force;
  tangent = b.transpose() * local_tangent * b;

  const double axial_force = local_force[0];
  const Vector3 moment_i = local_force.segment<3>(1);
  const Vector3 moment_j = local_force.segment<3>(4);
  const Vector3 spin_moment_i = jacobian_i.transpose() * moment_i; // m~_i = J^-T m_i
  const Vector3 spin_moment_j = jacobian_j.transpose() * moment_j;

  // (1) chord rotation at fixed axial force: d r1 = (I - r1 r1^T)(du_j - du_i) / l.
  const Block chord_rate =
      (Matrix3::Identity() - r1 * r1.transpose()) / l * (select_uj - select_ui);
  tangent.middleRows<3>(0) -= axial_force * chord_rate;
  tangent.middleRows<3>(6) += axial_force * chord_rate;

  // (2) derivative of J^-T at fixed moments: d m~_k = H_k J^-1 d w_bar_k.
  tangent += spin_i.transpose() * inverse_left_jacobian_transpose_derivative(theta_i, moment_i) *
             b.middleRows<3>(1);
  tangent += spin_j.transpose() * inverse_left_jacobian_transpose_derivative(theta_j, moment_j) *
             b.middleRows<3>(4);

  // (3) rotation of R_r in the term S_wk^T R_r m~_k: d(R_r m~) = -[R_r m~]x dw_r, dw_r = R_r Omega
  // d_g.
  const Block frame_spin = frame_ * omega;
  tangent.middleRows<3>(3) -= skew(frame_ * spin_moment_i) * frame_spin;
  tangent.middleRows<3>(9) -= skew(frame_ * spin_moment_j) * frame_spin;

  // (4) variation of Omega^T in the term -Omega^T (m~_i + m~_j) at fixed m~.
  const Vector3 mu = spin_moment_i + spin_moment_j;
  const Eigen::Matrix<double, 1, 12> length_rate = b.row(0);
  const Block r2_rate = -skew(r2) * frame_spin;
  const Block r3_rate = -skew(r3) * frame_spin;
  const Block director_i_rate = -skew(director_i_) * select_wi;
  const Block director_j_rate = -skew(director_j_) * select_wj;
  const Block mean_director_rate = 0.5 * (director_i_rate + director_j_rate);
  const Eigen::Matrix<double, 1, 12> q1_rate =
      r1.transpose() * mean_director_rate + p.transpose() * chord_rate;
  const Eigen::Matrix<double, 1, 12> q2_rate =
      r2.transpose() * mean_director_rate + p.transpose() * r2_rate;

  // Omega row 0 has a = q1 r3 / (l q2) at u_i (-a at u_j) and b_k = (p_k x r3) / (2 q2) at w_k.
  const Block a_rate =
      r3 * (q1_rate / (l * q2) - q1 * length_rate / (l * l * q2) - q1 * q2_rate / (l * q2 * q2)) +
      q1 / (l * q2) * r3_rate;
  const auto b_rate = [&](const Vector3& director, const Block& director_rate) -> Block {
    return (-skew(r3) * director_rate + skew(director) * r3_rate) / (2.0 * q2) -
           director.cross(r3) * q2_rate / (2.0 * q2 * q2);
  };
  const Block translation_term = mu[2] * (r2_rate / l - r2 * length_rate / (l * l)) -
                                 mu[1] * (r3_rate / l - r3 * length_rate / (l * l)) -
                                 mu[0] * a_rate;
  tangent.middleRows<3>(0) += translation_term;
  tangent.middleRows<3>(6) -= translation_term;
  tangent.middleRows<3>(3) -= mu[0] * b_rate(director_i_, director_i_rate);
  tangent.middleRows<3>(9) -= mu[0] * b_rate(director_j_, director_j_rate);
}

} // namespace brb::element
