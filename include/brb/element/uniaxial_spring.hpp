// UniaxialSpring: a zero-length link between two nodes with one uniaxial law per chosen DOF
// of a fixed set of axes Q (columns: the spring's x, y, z; global by default), DESIGN.md
// section 4 `Spring`. The axes do not follow the nodes (as OpenSees' zeroLength).
//
// Deformations, in the spring's axes:
//   translations  delta_u = Q^T ((x_j - x_i) - (X_j - X_i))    (mm; X the reference positions)
//   rotations     delta_r = Q^T theta,  theta = log(R_j R_i^T)  (rad; relative_rotation.hpp)
// Each active DOF a has a law (UniaxialLaw) read as force-deformation through two scales:
//   F_a = s_F sigma(delta_a / s_d),  dF_a/d delta_a = s_F E_t / s_d,
// so with s_F = s_d = 1 the law's "E" is the stiffness k (N/mm or N mm/rad) and its "fy" the
// yield force (N) or moment (N mm); a bar of area A and length L is s_F = A, s_d = L. The
// characteristic length of a damage law is s_d. Forces on node j: f_j = Q F_u (f_i = -f_j);
// moments: g = Q F_r is the moment conjugate to theta, turned into nodal moments exactly
// (relative_rotation_response). Energies: s_F s_d times the law's free and dissipated
// energy per unit volume, summed over the DOF.
#pragma once

#include "brb/element/element.hpp"
#include "brb/element/uniaxial_law.hpp"

#include <array>
#include <optional>
#include <vector>

namespace brb::element {

/// The law of one spring DOF and its scales.
struct SpringDofLaw {
  UniaxialLaw law;
  double force_scale = 1.0;       ///< s_F: force (N or N mm) per unit stress of the law
  double deformation_scale = 1.0; ///< s_d: deformation (mm or rad) per unit strain of the law
};

/// Spring DOF in the order of the spring's axes: ux, uy, uz, rx, ry, rz.
using SpringDofLaws = std::array<std::optional<SpringDofLaw>, 6>;

class UniaxialSpring final : public Element {
public:
  /// Throws ParameterError: "dofs" when no DOF has a law or a scale is not > 0, "axes" when
  /// the axes are not orthonormal.
  UniaxialSpring(std::array<int, 2> nodes, const Vector3& position_i, const Vector3& position_j,
                 SpringDofLaws laws, const Matrix3& axes = Matrix3::Identity());

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override;
  void commit() override;
  void revert_to_committed() override;
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  void save_state(io::StateWriter& out) const override { out(*this); }
  void load_state(io::StateReader& in) override {
    in(*this);
    revert_to_committed();
  }
  /// Checkpoints: each channel's committed law state, then the last evaluation's outputs.
  template <class Archive, class Self>
  requires io::state_of<Self, UniaxialSpring>
  friend void state_fields(Archive& archive, Self& spring) {
    for (auto& channel : spring.channels_)
      archive(channel.committed);
    archive(spring.deformation_, spring.dof_force_, spring.energy_);
  }
  ElementEnergy energy() const override { return energy_; }

  /// Of the last evaluation, per DOF in the spring's axes (zero where no law):
  /// deformations (mm, rad) and forces (N, N mm).
  const Eigen::Matrix<double, 6, 1>& deformation() const { return deformation_; }
  const Eigen::Matrix<double, 6, 1>& dof_force() const { return dof_force_; }
  const Matrix3& axes() const { return axes_; }

private:
  struct Channel {
    int dof = 0;
    SpringDofLaw law;
    UniaxialLaw::State committed;
    UniaxialLaw::State trial;
  };

  std::array<int, 2> nodes_;
  Vector3 reference_offset_; ///< X_j - X_i
  Matrix3 axes_;
  std::vector<Channel> channels_;
  bool has_rotations_ = false;
  Eigen::Matrix<double, 6, 1> deformation_ = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> dof_force_ = Eigen::Matrix<double, 6, 1>::Zero();
  ElementEnergy energy_;
};

} // namespace brb::element
