// Model: nodes with six degrees of freedom (three translations, three rotations), their
// fixities, nodal masses, multi-point constraints (equal DOF, rigid floor diaphragms) and the
// elements between them. A 2D analysis is a 3D model whose out-of-plane DOF are removed by
// the DOF map (dof_map.hpp; one code path). Units: mm, N, tonne.
#pragma once

#include "brb/element/element.hpp"

#include <array>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace brb::model {

using element::Matrix3;
using element::Vector3;

inline constexpr int kDofPerNode = 6;

/// Degrees of freedom of a node, in the order of the global vectors.
enum Dof : int { ux = 0, uy = 1, uz = 2, rx = 3, ry = 4, rz = 5 };

/// Lumped nodal mass: translational masses (tonne) on ux, uy, uz and rotational inertias
/// (tonne mm^2) on rx, ry, rz.
using NodalMass = std::array<double, kDofPerNode>;

/// The listed DOF of `slave` equal those of `master` (small displacements).
struct EqualDofConstraint {
  int master = -1;
  int slave = -1;
  std::vector<Dof> dofs;
};

/// A rigid floor slab in the plane normal to global Z: the in-plane motion (ux, uy, rz) of
/// each slave follows the master's rigid-body motion, u_s = u_m - (y_s - y_m) rz_m,
/// v_s = v_m + (x_s - x_m) rz_m, rz_s = rz_m (small in-plane rotation of the slab).
struct RigidDiaphragmConstraint {
  int master = -1;
  std::vector<int> slaves;
};

class Model {
public:
  /// Adds a node at `coordinates` (mm); returns its index. `axes` (columns) are the node's
  /// own directions, e.g. a brace's axis and section axes: solvers that weigh DOF by
  /// direction (the pseudo-transient viscosity of StaticAnalysis) use them, so that a turned
  /// model behaves as the unturned one. Default: the global axes.
  int add_node(const Vector3& coordinates, const Matrix3& axes = Matrix3::Identity());
  const Matrix3& node_axes(int node) const { return axes_.at(node); }

  /// Restrains one DOF of a node (displacement zero for ever).
  void fix(int node, Dof dof);
  /// Restrains all six DOF.
  void fix_all(int node);

  /// Adds a lumped mass to a node (masses add up); each component >= 0.
  void add_mass(int node, const NodalMass& mass);
  const NodalMass& mass(int node) const { return masses_.at(node); }
  /// Whether any node carries mass.
  bool has_mass() const;

  /// Multi-point constraints; the DOF map resolves them (chains of constraints allowed,
  /// cycles and a DOF slaved twice are errors).
  void add_equal_dof(EqualDofConstraint constraint);
  void add_rigid_diaphragm(RigidDiaphragmConstraint constraint);
  std::span<const EqualDofConstraint> equal_dofs() const { return equal_dofs_; }
  std::span<const RigidDiaphragmConstraint> rigid_diaphragms() const { return diaphragms_; }

  /// Adds an element whose nodes() refer to existing nodes; returns a reference to it.
  template <class ElementType> ElementType& add_element(std::unique_ptr<ElementType> element) {
    ElementType& reference = *element;
    check_element_nodes(reference);
    elements_.push_back(std::move(element));
    return reference;
  }

  int node_count() const { return static_cast<int>(coordinates_.size()); }
  int dof_count() const { return kDofPerNode * node_count(); }
  const Vector3& coordinates(int node) const { return coordinates_.at(node); }
  bool is_fixed(int node, Dof dof) const { return fixed_.at(node)[dof]; }
  /// Global index of a node's DOF in full-length vectors.
  static int global_dof(int node, Dof dof) { return kDofPerNode * node + dof; }

  std::span<const std::unique_ptr<element::Element>> elements() const { return elements_; }

  /// A rule that a static analysis runs after each commit, which may change the committed
  /// state of some elements from that of others (a mortar casing's beams split by the split of
  /// its contact links' walls: brace_model.cpp). It refers to elements by their index, so
  /// that a twin model built from the same data carries the same rule, and returns whether
  /// it changed anything (the analysis then re-evaluates the committed forces).
  using CommitCoupling = std::function<bool(std::span<const std::unique_ptr<element::Element>>)>;
  void add_commit_coupling(CommitCoupling coupling) { couplings_.push_back(std::move(coupling)); }
  /// Runs every commit coupling; whether any changed a committed state.
  bool apply_commit_couplings() const {
    bool changed = false;
    for (const auto& coupling : couplings_)
      changed = coupling(elements_) || changed;
    return changed;
  }
  /// Takes over the state of every element of `other`, a twin model built from the same data
  /// (same elements in the same order; see Element::copy_state_from).
  void copy_element_states_from(const Model& other);

private:
  void check_element_nodes(const element::Element& element) const;
  void check_node(int node, const std::string& what) const;

  std::vector<Vector3> coordinates_;
  std::vector<Matrix3> axes_;
  std::vector<std::array<bool, kDofPerNode>> fixed_;
  std::vector<NodalMass> masses_;
  std::vector<EqualDofConstraint> equal_dofs_;
  std::vector<RigidDiaphragmConstraint> diaphragms_;
  std::vector<std::unique_ptr<element::Element>> elements_;
  std::vector<CommitCoupling> couplings_;
};

} // namespace brb::model
