// ZeroLengthSpring: linear springs between two nodes, one per DOF of a fixed set of axes
// (global by default; a brace's axis and section axes for its stopper, DESIGN.md section 4:
// the stopper that ties a BRB casing to its core at mid-length, axially and in twist).
// With axes Q (columns), the stiffness matrices are Q diag(k) Q^T (symmetric), which the
// formulas below take as they are.
//
// Translations: f = K_u (u_j - u_i), u the nodal displacement from the reference positions.
// Rotations: the relative rotation vector theta = log(R_j R_i^T) in global axes, with the
// potential V = 1/2 theta^T K_r theta. With spins R <- exp([dw]x) R (element.hpp),
//   d theta = J^-1(theta) (dw_j - R_rel dw_i),  R_rel = R_j R_i^T,
// (rotation.hpp), so the moments are m_j = J^-T K_r theta and m_i = -R_rel^T m_j; the
// tangent differentiates both exactly (it is non-symmetric once theta is finite, as spin
// variables are not a parametrisation). Stiffnesses: N/mm and N mm/rad, each >= 0.
#pragma once

#include "brb/element/element.hpp"

#include <array>

namespace brb::element {

/// Stiffness per DOF of the spring's axes: ux, uy, uz (N/mm), rx, ry, rz (N mm/rad).
using SpringStiffness = std::array<double, 6>;

class ZeroLengthSpring final : public Element {
public:
  /// nodes {i, j}; the reference positions fix the unstretched state (they need not
  /// coincide). `axes`: columns are the directions of the springs' x, y, z (orthonormal).
  /// Throws ParameterError ("stiffness", "axes") for a negative or non-finite value or axes
  /// that are not orthonormal.
  ZeroLengthSpring(std::array<int, 2> nodes, const Vector3& position_i, const Vector3& position_j,
                   const SpringStiffness& stiffness, const Matrix3& axes = Matrix3::Identity());

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override;
  void commit() override {}
  void revert_to_committed() override {}
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  /// Elastic: no history; the last evaluation's force, moment and energy.
  void save_state(io::StateWriter& out) const override { out(*this); }
  void load_state(io::StateReader& in) override { in(*this); }
  template <class Archive, class Self>
  requires io::state_of<Self, ZeroLengthSpring>
  friend void state_fields(Archive& archive, Self& spring) {
    archive(spring.spring_force_, spring.spring_moment_, spring.stored_energy_);
  }
  ElementEnergy energy() const override { return {stored_energy_, 0.0}; }

  /// Force on node j (N; reaction of the translational springs) of the last evaluation.
  const Vector3& spring_force() const { return spring_force_; }
  /// Moment on node j (N mm) of the last evaluation.
  const Vector3& spring_moment() const { return spring_moment_; }

private:
  std::array<int, 2> nodes_;
  Vector3 reference_offset_;        ///< X_j - X_i
  Matrix3 translational_stiffness_; ///< Q diag(k_u) Q^T (global)
  Matrix3 rotational_stiffness_;    ///< Q diag(k_r) Q^T (global)
  Vector3 spring_force_ = Vector3::Zero();
  Vector3 spring_moment_ = Vector3::Zero();
  double stored_energy_ = 0.0;
};

} // namespace brb::element
