// A shallow two-bar (von Mises) truss for tests of limit points: half-span 1000 mm, rise
// 50 mm, elastic steel bars of 100 mm^2, loaded at its apex through a soft spring (5 N/mm)
// whose far end (`driver`, 1000 mm above the apex) the test moves. The truss's force on its
// apex peaks and then falls faster than the spring can follow, so the driven path has a limit
// point and the apex snaps through to the inverted configuration.
#pragma once

#include "brb/element/corot_truss.hpp"
#include "brb/material/steel_uniaxial.hpp"
#include "brb/model/model.hpp"

#include <array>
#include <memory>

namespace brb::test {

struct ShallowTruss {
  model::Model model;
  int apex = 0;
  int driver = 0;
};

/// The supports fixed, the apex free along y only; the driver left free (a test fixes its
/// other DOF or prescribes its motion). Owned by pointer: the model is not movable once built.
inline std::unique_ptr<ShallowTruss> shallow_truss() {
  using Truss = element::CorotTruss<material::SteelUniaxial>;
  auto truss = std::make_unique<ShallowTruss>();
  model::Model& model = truss->model;
  const int left = model.add_node({-1000.0, 0.0, 0.0});
  const int right = model.add_node({1000.0, 0.0, 0.0});
  truss->apex = model.add_node({0.0, 50.0, 0.0});
  truss->driver = model.add_node({0.0, 1050.0, 0.0});
  material::SteelParameters steel;
  steel.youngs_modulus = 210000.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 1e9; // elastic throughout
  const auto bar = [&](int a, int b, double area) {
    model.add_element(std::make_unique<Truss>(std::array<int, 2>{a, b}, model.coordinates(a),
                                              model.coordinates(b), area,
                                              material::SteelUniaxial(steel, 1.0)));
  };
  bar(left, truss->apex, 100.0);
  bar(right, truss->apex, 100.0);
  bar(truss->apex, truss->driver, 5.0 * 1000.0 / 210000.0); // spring k = E A / L = 5 N/mm
  model.fix_all(left);
  model.fix_all(right);
  for (const auto dof : {model::ux, model::uz, model::rx, model::ry, model::rz})
    model.fix(truss->apex, dof);
  return truss;
}

} // namespace brb::test
