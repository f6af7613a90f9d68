// ElasticBeamColumn: a two-node elastic 3D beam-column (Euler-Bernoulli, E, G, A, Iy, Iz, J)
// for the members of a frame (DESIGN.md section 4), with three geometries:
//
// - linear: the classic 12x12 Euler-Bernoulli stiffness K_l in the local axes (McGuire,
//   Gallagher & Ziemian, Matrix Structural Analysis, 2nd ed., 2000, ch. 4), K = L^T K_l L
//   with L = blockdiag(T^T) and T = [x y z] the initial local axes. The nodal rotations are
//   the rotation vectors theta_k = log(R_k) of the nodal triads, so the strain energy is
//   V = 1/2 d^T K d, d = [u_i, theta_i, u_j, theta_j] (u = x - X). Forces are its gradient
//   with respect to translations and spins: q = K d on the translations and J^-T(theta_k) q
//   on the rotations (d theta = J^-1 dw, rotation.hpp); J^-T = I to first order, so this is
//   the classic K d for small rotations, and the element stays exactly conservative.
// - pdelta: linear plus the P-Delta effect of the chord (OpenSees PDeltaCrdTransf3d): with
//   N = E A / L x . (u_j - u_i) from the linear axial strain and the transverse chord offset
//   a = (I - x x^T)(u_j - u_i), the nodal forces gain -/+ N a / L; the tangent gains
//   N / L (I - x x^T) (the geometric stiffness on the transverse translations, which reduces
//   a leaning column's lateral stiffness by exactly P / h) and the consistent coupling
//   E A / L^2 a x^T. The stored energy includes the P-Delta potential N |a|^2 / (2 L),
//   so that the work of the P-Delta forces is accounted for (exactly while N is constant,
//   e.g. under gravity), and an energy balance of a frame with leaning columns closes.
// - corotational: large displacements and rotations, the co-rotational frame of
//   corotational_frame.hpp around the elastic local beam: N = E A u_bar / L,
//   m_i = E I / L (4 theta_i + 2 theta_j), m_j = E I / L (2 theta_i + 4 theta_j) in each
//   bending plane (E Iy for the rotations about local y, E Iz about local z), torque
//   G J (theta_jx - theta_ix) / L. Stored energy 1/2 f_l . d_l.
//
// Local axes (OpenSees vecxz): x from node i to node j, z the normalised component of the
// orientation vector orthogonal to x, y = z x x. Iy = int z^2 dA governs bending about local
// y (deflection along z), Iz about local z (deflection along y), as the fiber sections'
// eps = e0 + z kappa_y - y kappa_z. Units: mm, MPa, N; forces N and N mm; nothing is
// dissipated.
#pragma once

#include "brb/element/corotational_frame.hpp"
#include "brb/element/element.hpp"

#include <array>

namespace brb::element {

enum class BeamGeometry { linear, pdelta, corotational };

/// Elastic section properties (the frame file's "sections" entries).
struct ElasticBeamProperties {
  double youngs_modulus = 0.0;   ///< E (MPa)
  double shear_modulus = 0.0;    ///< G (MPa)
  double area = 0.0;             ///< A (mm^2)
  double inertia_y = 0.0;        ///< Iy = int z^2 dA (mm^4), bending about local y
  double inertia_z = 0.0;        ///< Iz = int y^2 dA (mm^4), bending about local z
  double torsion_constant = 0.0; ///< J (mm^4)

  /// Throws ParameterError naming the key (E, G, A, Iy, Iz, J) unless each is > 0 and finite.
  void validate() const;
};

using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Vector12 = Eigen::Matrix<double, 12, 1>;

class ElasticBeamColumn final : public Element {
public:
  /// `orientation`: a vector in the local x-z plane. Throws ParameterError for invalid
  /// properties, a zero length ("nodes") or an orientation parallel to the axis
  /// ("orientation").
  ElasticBeamColumn(std::array<int, 2> nodes, const Vector3& position_i, const Vector3& position_j,
                    const ElasticBeamProperties& properties, const Vector3& orientation,
                    BeamGeometry geometry);

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override;
  void commit() override {}
  void revert_to_committed() override {}
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  /// Elastic: no history; the last evaluation's frame, energy and axial force.
  void save_state(io::StateWriter& out) const override { out(*this); }
  void load_state(io::StateReader& in) override { in(*this); }
  template <class Archive, class Self>
  requires io::state_of<Self, ElasticBeamColumn>
  friend void state_fields(Archive& archive, Self& beam) {
    archive(beam.frame_, beam.stored_energy_, beam.axial_force_);
  }
  ElementEnergy energy() const override { return {stored_energy_, 0.0}; }

  BeamGeometry geometry() const { return geometry_; }
  const ElasticBeamProperties& properties() const { return properties_; }
  double length() const { return frame_.initial_length(); }
  /// Initial local axes: columns x, y, z.
  const Matrix3& local_axes() const { return frame_.initial_frame(); }
  /// The 12x12 elastic stiffness in local axes, DOF order [u_i, theta_i, u_j, theta_j].
  Matrix12 local_stiffness() const;
  /// Axial force N of the last evaluation (N, tension positive).
  double axial_force() const { return axial_force_; }

private:
  void evaluate_small_displacement(std::span<const NodeConfiguration> configuration,
                                   Eigen::VectorXd& force, Eigen::MatrixXd& tangent);
  bool evaluate_corotational(std::span<const NodeConfiguration> configuration,
                             Eigen::VectorXd& force, Eigen::MatrixXd& tangent,
                             std::string& failure);

  std::array<int, 2> nodes_;
  std::array<Vector3, 2> reference_position_;
  ElasticBeamProperties properties_;
  BeamGeometry geometry_;
  CorotationalFrame frame_;        ///< initial axes for every geometry; moved by corotational
  Matrix12 global_stiffness_;      ///< L^T K_l L (linear and pdelta)
  LocalMatrix corotational_local_; ///< the 7x7 local stiffness of the co-rotational beam
  double stored_energy_ = 0.0;
  double axial_force_ = 0.0;
};

} // namespace brb::element
