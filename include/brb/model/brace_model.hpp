// The finite element model of a brace from its BraceSpec: a chain of co-rotational fiber
// beams along global x (connection, transition, yielding core, transition, connection),
// with the initial imperfection, end conditions, and the brace's nominal yield force and
// yield deformation. Section axes: y along global Y, z along global Z.
#pragma once

#include "brb/element/corot_beam_3d.hpp"
#include "brb/material/steel_uniaxial.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/model/model.hpp"
#include "brb/section/fiber_section.hpp"

#include <vector>

namespace brb::model {

using CoreSection = section::FiberSection<material::SteelUniaxial>;
using CoreBeam = element::CorotBeam3D<CoreSection>;

struct BraceModel {
  Model model;
  int start_node = 0;                 ///< fixed end (work point)
  int end_node = 0;                   ///< driven end: its x displacement is the deformation
  std::vector<int> nodes;             ///< all nodes from start to end
  std::vector<CoreBeam*> beams;       ///< all elements from start to end
  std::vector<bool> in_yielding_zone; ///< per element
  double core_area = 0.0;             ///< mm^2
  double yield_force = 0.0;           ///< fy A_core (N)
  /// Axial deformation between the outer nodes at first yield of the core (mm): the series
  /// flexibility of the zones, P_y sum L / (E A).
  double yield_deformation = 0.0;
};

/// Builds the model of a bare core (the casing is not modelled yet). Throws ParameterError
/// (with the key of the brace schema) on inconsistent geometry.
BraceModel build_brace_model(const BraceSpec& spec);

/// Lateral offsets (global Y, Z per node, mm) of the first elastic buckling mode of the
/// perfect brace, scaled so that the largest lateral offset is 1 mm.
std::vector<std::pair<double, double>> first_buckling_mode(const BraceSpec& spec);

} // namespace brb::model
