// CasingContact: the link between a core node and the casing node at the same station
// (DESIGN.md section 4, BRB_SOURCE_FACTS sections 3-4). In each transverse direction
// (section y and z) the core has a clearance `gap` to the casing on both sides; once it
// closes, the core bears on the mortar: the bearing stress follows the mortar damage law at
// the strain penetration / bearing depth (the mortar's thickness in that direction), over
// the bearing area (local crushing softens it,
// and each of the four faces keeps its own damage). An always-active soft spring models the
// unbonding layer (it keeps the casing stable while gaps are open). Along the axis, Coulomb
// friction acts with the total bearing force as normal force.
//
// Directions are the initial (global) axes of the brace: the link is geometrically linear,
// which is exact for the small rotations of the casing relative to the core's axis.
// DOF: 6 per node (translations used), force on the core = -force on the casing.
//
// Open links (DESIGN.md section 10): while no face is penetrated only the layer spring acts
// (friction has no normal force: zero force and tangent, its slip follows the axial motion),
// so the tangent is the constant layer tangent, kept from construction; the bearing and
// friction laws are not called. `skip_open_links` false takes the general path (the
// benchmark's reference); both give the same numbers bit for bit.
#pragma once

#include "brb/element/element.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/penalty_friction.hpp"

#include <array>

namespace brb::element {

struct CasingContactParameters {
  Matrix3 axes = Matrix3::Identity(); ///< columns: brace axis, section y, section z (global)
  double gap_y = 0.0;                 ///< clearance on each side along y (mm), >= 0
  double gap_z = 0.0;                 ///< clearance on each side along z (mm), >= 0
  double bearing_area_y = 0.0;        ///< area bearing on a y face (mm^2)
  double bearing_area_z = 0.0;        ///< area bearing on a z face (mm^2)
  /// Mortar depth turning penetration into strain on a y face and on a z face (mm): the
  /// mortar's thickness in that direction (a plate core in a square tube has two).
  double bearing_depth_y = 0.0;
  double bearing_depth_z = 0.0;
  material::MortarParameters mortar; ///< bearing law
  double layer_stiffness = 0.0;      ///< unbonding layer spring per direction (N/mm), >= 0
  double friction_coefficient = 0.1; ///< kappa (source: 0.1)
  double tangential_stiffness = 0.0; ///< stick penalty along the axis (N/mm)

  /// Throws ParameterError naming the key (gap_y, gap_z, bearing_area_y, ...).
  void validate() const;
};

class CasingContact final : public Element {
public:
  /// nodes: {core node, casing node}, coincident in the reference configuration up to the
  /// initial imperfection (the relative displacement counts from the initial offset).
  CasingContact(std::array<int, 2> nodes, const Vector3& core_position,
                const Vector3& casing_position, const CasingContactParameters& parameters,
                bool skip_open_links = true);

  std::span<const int> nodes() const override { return nodes_; }
  bool evaluate(std::span<const NodeConfiguration> configuration, Eigen::VectorXd& force,
                Eigen::MatrixXd& tangent, std::string& failure) override;
  void commit() override { committed_ = trial_; }
  void revert_to_committed() override { trial_ = committed_; }
  void copy_state_from(const Element& other) override { copy_element_value(*this, other); }
  ElementEnergy energy() const override;

  /// Bearing force on the core per direction (N, along y and z, resisting) and friction (N).
  const Vector3& link_force() const { return link_force_; }
  /// Largest mortar damage over the four faces (trial state).
  double max_mortar_damage() const;
  /// Whether any face is in contact (trial state).
  bool in_contact() const { return in_contact_; }
  /// Evaluations that took the open-link path (for the benchmark and its tests).
  long open_evaluations() const { return open_evaluations_; }

private:
  struct State {
    std::array<material::MortarState, 4> faces{}; ///< +y, -y, +z, -z
    material::FrictionState friction;
    std::array<double, 4> bearing_strain{}; ///< for the free energy
  };

  std::array<int, 2> nodes_;
  Vector3 initial_offset_;
  CasingContactParameters parameters_;
  /// Bearing law of the y faces and of the z faces (their characteristic lengths are the
  /// bearing depths, so that crushing dissipates G_f per unit area of face).
  std::array<material::MortarUniaxial, 2> bearing_;
  material::PenaltyFriction friction_;
  State committed_;
  State trial_;
  Vector3 relative_ = Vector3::Zero(); ///< local relative displacement (axis, y, z)
  Vector3 link_force_ = Vector3::Zero();
  bool in_contact_ = false;
  bool skip_open_links_ = true;
  Eigen::MatrixXd open_tangent_; ///< 12 x 12 tangent of an open link (layer springs only)
  long open_evaluations_ = 0;

  /// The local tangent (axis, y, z) when every face is open, and the force and tangent
  /// scattered onto the two nodes (shared by both paths so that they round alike).
  Matrix3 open_local_tangent() const;
  void scatter(const Vector3& local_force, const Matrix3& local_tangent, Eigen::VectorXd& force,
               Eigen::MatrixXd& tangent) const;
};

} // namespace brb::element
