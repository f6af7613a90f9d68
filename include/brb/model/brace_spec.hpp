// BraceSpec: what a brace is, as the user describes it (the `brb` brace schema of the
// README), independent of how it is read. Units: mm, N, MPa.
//
// Geometry along the brace axis (global x), symmetric about mid-length:
//   connection | transition | yielding core | transition | connection
// The casing (issue "BRB element") is not modelled yet: `casing: null` is the bare core.
#pragma once

#include "brb/element/beam_integration.hpp"
#include "brb/material/steel_parameters.hpp"
#include "brb/section/fiber_layout.hpp"

#include <optional>
#include <string>

namespace brb::model {

enum class SectionShape { rectangle, circle, cruciform, rectangular_tube, circular_tube };

/// A cross-section and its fiber density. Dimensions by shape:
/// rectangle: width (y), depth (z); circle: diameter; cruciform: width, depth, thickness;
/// rectangular_tube: width, depth, wall; circular_tube: diameter, wall.
/// Fiber counts: rectangle (fibers_y, fibers_z); circle and circular tube (rings, sectors);
/// cruciform and rectangular tube (along, through).
struct SectionSpec {
  SectionShape shape = SectionShape::rectangle;
  double width = 0.0, depth = 0.0, diameter = 0.0, thickness = 0.0, wall = 0.0;
  int fibers_a = 0, fibers_b = 0;

  section::FiberLayout mesh() const;
};

struct ZoneSpec {
  double length = 0.0; ///< mm, each end
  SectionSpec section;
  int elements = 1; ///< per end
};

enum class EndCondition { pinned, fixed };
enum class ImperfectionShape { bow, buckling_mode };
enum class BendingAxis { y, z }; ///< lateral direction of the imperfection (section axis)

struct ImperfectionSpec {
  ImperfectionShape shape = ImperfectionShape::bow;
  double amplitude = 0.0; ///< mm, largest lateral offset of the core axis
  BendingAxis direction = BendingAxis::z;
};

struct BraceSpec {
  std::string name;
  SectionSpec core_section;
  material::SteelParameters steel;
  double yielding_length = 0.0; ///< mm
  int core_elements = 16;
  element::IntegrationRule integration_rule = element::IntegrationRule::gauss_lobatto;
  int integration_points = 3;
  std::optional<ZoneSpec> transition;
  std::optional<ZoneSpec> connection;
  EndCondition ends = EndCondition::pinned;
  ImperfectionSpec imperfection;

  /// Length between the outer nodes (work points), mm.
  double total_length() const;
};

} // namespace brb::model
