// Brace specifications shared by tests and benchmarks.
#pragma once

#include "brb/model/brace_spec.hpp"

namespace brb::test {

/// The Girona D3 core (BRB_SOURCE_FACTS section 7): round S275 core d = 22 mm, yielding
/// length 2196 mm, connectors d = 85 mm over 270 mm; the 36 mm transitions are given an
/// assumed d = 40 mm. Bare core (no casing), pinned ends, bow L/1000 in z.
inline model::BraceSpec girona_d3_bare_core(int core_elements = 16, bool with_end_zones = true) {
  model::BraceSpec spec;
  spec.name = "girona_D3_bare";
  spec.core_section.shape = model::SectionShape::circle;
  spec.core_section.diameter = 22.0;
  spec.core_section.fibers_a = 4;
  spec.core_section.fibers_b = 16;
  spec.steel.youngs_modulus = 210000.0;
  spec.steel.poissons_ratio = 0.3;
  spec.steel.yield_stress = 275.0;
  spec.steel.kinematic_hardening = 21000.0;
  spec.yielding_length = 2196.0;
  spec.core_elements = core_elements;
  if (with_end_zones) {
    model::ZoneSpec connection;
    connection.length = 270.0;
    connection.section.shape = model::SectionShape::circle;
    connection.section.diameter = 85.0;
    connection.section.fibers_a = 2;
    connection.section.fibers_b = 8;
    model::ZoneSpec transition = connection;
    transition.length = 36.0;
    transition.section.diameter = 40.0;
    spec.connection = connection;
    spec.transition = transition;
  }
  spec.imperfection = {model::ImperfectionShape::bow, spec.total_length() / 1000.0,
                       model::BendingAxis::z};
  return spec;
}

/// The Girona D3 brace (BRB_SOURCE_FACTS section 7) without end zones, pinned, bow L/1000,
/// in its casing: core d 22 mm over 2196 mm; casing tube d 115 wall 3 (S275-like, H_kin
/// 2100 MPa), mortar E 17520, nu 0.2, fc 50, ft 5 MPa, Gf 0.1 N/mm (assumed: the source gives
/// none), gap 0.5 mm per side (assumed), friction 0.1 (section 4).
inline model::BraceSpec girona_d3_restrained(int core_elements = 16) {
  model::BraceSpec spec = girona_d3_bare_core(core_elements, false);
  spec.name = "girona_D3_restrained";
  model::CasingSpec casing;
  casing.tube.shape = model::SectionShape::circular_tube;
  casing.tube.diameter = 115.0;
  casing.tube.wall = 3.0;
  casing.tube.fibers_a = 1;
  casing.tube.fibers_b = 16;
  casing.tube_steel = spec.steel;
  casing.tube_steel.kinematic_hardening = 2100.0;
  casing.mortar = {17520.0, 0.2, 50.0, 5.0, 0.1};
  casing.fill_fibers_a = 2;
  casing.fill_fibers_b = 16;
  casing.gap_y = casing.gap_z = 0.5;
  spec.casing = casing;
  return spec;
}

} // namespace brb::test
