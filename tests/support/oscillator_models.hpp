// Small dynamic models for the transient and modal analysis tests: single-DOF oscillators
// (a node moving in global X on a zero-length spring to a fixed node) and the shear building
// (floors stacked along Z, storey springs in X).
#pragma once

#include "brb/element/zero_length_spring.hpp"
#include "brb/model/model.hpp"

#include <memory>

namespace brb::test {

/// Fixes every DOF of `node` but ux.
inline void free_only_ux(model::Model& model, int node) {
  for (const model::Dof dof : {model::uy, model::uz, model::rx, model::ry, model::rz})
    model.fix(node, dof);
}

/// Adds a node at (x, 0, z) that moves only along X, with translational mass `mass` in X.
inline int add_x_oscillator_node(model::Model& model, double x, double z, double mass) {
  const int node = model.add_node({x, 0.0, z});
  free_only_ux(model, node);
  if (mass > 0.0)
    model.add_mass(node, {mass, 0.0, 0.0, 0.0, 0.0, 0.0});
  return node;
}

/// A spring of stiffness k (N/mm) along X between two nodes.
inline void add_x_spring(model::Model& model, int i, int j, double stiffness) {
  model.add_element(std::make_unique<element::ZeroLengthSpring>(
      std::array<int, 2>{i, j}, model.coordinates(i), model.coordinates(j),
      element::SpringStiffness{stiffness, 0.0, 0.0, 0.0, 0.0, 0.0}));
}

/// Ground node 0 (fixed) and one oscillator node 1 of mass m on a spring k along X.
inline model::Model single_oscillator(double mass, double stiffness) {
  model::Model model;
  const int ground = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(ground);
  const int node = add_x_oscillator_node(model, 1000.0, 0.0, mass);
  add_x_spring(model, ground, node, stiffness);
  return model;
}

/// n storeys of height h: node 0 fixed at the base, node i at z = i h with mass m in X, a
/// storey spring k in X between consecutive floors. With `split_storeys`, each storey is two
/// springs 2k in series through a massless mid-height node (same storey stiffness).
inline model::Model shear_building(int storeys, double mass, double stiffness,
                                   bool split_storeys = false, double height = 3000.0) {
  model::Model model;
  int below = model.add_node({0.0, 0.0, 0.0});
  model.fix_all(below);
  for (int storey = 1; storey <= storeys; ++storey) {
    const int floor = add_x_oscillator_node(model, 0.0, storey * height, mass);
    if (split_storeys) {
      const int middle = add_x_oscillator_node(model, 0.0, (storey - 0.5) * height, 0.0);
      add_x_spring(model, below, middle, 2.0 * stiffness);
      add_x_spring(model, middle, floor, 2.0 * stiffness);
    } else {
      add_x_spring(model, below, floor, stiffness);
    }
    below = floor;
  }
  return model;
}

} // namespace brb::test
