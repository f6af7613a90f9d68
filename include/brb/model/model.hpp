// Model: nodes with six degrees of freedom (three translations, three rotations), their
// fixities, and the elements between them. A 2D analysis is a 3D model whose
// out-of-plane DOF are fixed (one code path). Units: mm, N.
#pragma once

#include "brb/element/element.hpp"

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace brb::model {

using element::Vector3;

inline constexpr int kDofPerNode = 6;

/// Degrees of freedom of a node, in the order of the global vectors.
enum Dof : int { ux = 0, uy = 1, uz = 2, rx = 3, ry = 4, rz = 5 };

class Model {
public:
  /// Adds a node at `coordinates` (mm); returns its index.
  int add_node(const Vector3& coordinates);

  /// Restrains one DOF of a node (displacement zero for ever).
  void fix(int node, Dof dof);
  /// Restrains all six DOF.
  void fix_all(int node);

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

  /// Takes over the state of every element of `other`, a twin model built from the same data
  /// (same elements in the same order; see Element::copy_state_from).
  void copy_element_states_from(const Model& other);

private:
  void check_element_nodes(const element::Element& element) const;

  std::vector<Vector3> coordinates_;
  std::vector<std::array<bool, kDofPerNode>> fixed_;
  std::vector<std::unique_ptr<element::Element>> elements_;
};

} // namespace brb::model
