// The structured hexahedral mesh of a whole brace for the 3D continuum model (issue 6):
// the parts (core steel, mortar, steel tube), their maps to global nodes, the two contact
// face lists and the named node sets, from the same model::BraceSpec as `brb cyclic`.
//
// Geometry and its simplifications (each stated with its source):
// - Axis: the brace axis is global x, from the start work point (x = 0) to the driven end
//   (x = total_length()); the section's y and z are global y and z, centred on the axis.
//   Cross-sections are structured quad grids (tensor-product lines in y and z, cells masked
//   in or out) extruded along x through stations: every part is a structured hex mesh.
// - Core: a rectangle as it is; a circle as the square of equal area, side d sqrt(pi) / 2
//   (the source's replacement, BRB_SOURCE_FACTS section 7); a cruciform as the structured
//   union of a centre square (thickness x thickness) and four arms, one grid of lines at
//   +-width/2, +-thickness/2 in y and +-depth/2, +-thickness/2 in z. Other core shapes are
//   refused. elements_across_core elements across the smaller side (the cruciform's
//   thickness); the other directions get about the same element size (at least one element).
// - End zones (transition, connection) outside the casing: the core's grid scaled by (s_y,
//   s_z) per zone, same topology, conforming nodes. The scales match the zone's area A and
//   its weak-axis second moment I (exact closed forms of its SectionSpec): for weak-axis
//   bending in z (I_y = int z^2 dA the smaller), s_z = sqrt((I_y / A) / (I_y0 / A0)) and s_y =
//   A / (A0 s_z), the grid's A0, I_y0 (and symmetrically for y); the strong-axis I is not
//   matched. A station between two zones takes the section of the smaller (in area) of the
//   two, so the first element layer of the larger zone tapers linearly between the two
//   sections (a step cannot be conforming with one topology).
// - Casing: spans the yielding length plus casing.overlap into each transition; its
//   stations are the core's stations there. Opening: the core's (meshed, scaled) bounding
//   box + gap_y, gap_z per side (as the reduced model, brace_spec.hpp), centred on the core's
//   bowed axis at each station (the mortar is cast around the core as it is; the reduced
//   model's CasingContact likewise measures the gap from the initial offset). Mortar: the
//   rectangular ring from the opening to the tube's inner outline; the mortar that would fill
//   a cruciform's re-entrant corners is left out (as brace_spec.hpp's fill). Tube:
//   - rectangular_tube: its wall as a rectangular ring, one element through the wall;
//   - circular_tube: the square ring of the same wall t and the same area, outer side
//     a_o = pi (D - t) / 4 + t (mid-line perimeter 4 (a_o - t) = pi (D - t));
//   - without a steel tube (a mortar-only casing): the outline (circle: the equal-area
//     square) is the mortar's outer outline, no tube part;
//   - SolidTube::homogenised: no tube part; the mortar ring is widened by the same s on
//     every side until its weak-axis bending stiffness E_c I equals that of the mortar plus
//     the tube's square ring, E_c I_m + E_s I_t (n_E = E_s / E_c, the source's
//     homogenisation, section 7; for Girona D1/D2 this gives a 102.4 mm square against the
//     source's 103.92 mm, whose rule the source does not state).
//   Mortar and tube share the nodes of the tube's inner outline. The casing's elements
//   across the opening follow the core's element size.
// - Contact faces: core faces on the core's bounding-box outline (the faces that face the
//   casing across the gap; a cruciform's re-entrant faces face no casing and are left out)
//   and the mortar's faces around the opening, both over the casing's length; each quad is
//   numbered counter-clockwise seen from outside its own body, so its right-hand normal
//   points out of its body, into the gap.
// - Stopper (full length): a penalty tie of the mean axial displacement of the core's nodes
//   and of the casing's nodes at the casing station nearest casing.stopper_position
//   (AxialTie, axial_tie.hpp), stiffness casing.stopper_stiffness_ratio x E A_core / L_y as the
//   reduced model's stopper. Half length: the stopper is the symmetry plane (position 0.5 only).
// - Half length (the source's half model, section 7): from mid-length (x = total / 2) to the
//   driven end; the symmetry plane u_x = 0 holds core, mortar and tube at mid-length; the
//   yielding half gets half the full mesh's elements, so the half mesh is the full mesh's half.
// - Imperfection: the bow of the reduced model (brace_model.cpp, imperfection_offsets): every
//   core station is offset along the imperfection's direction by a sin(pi x / L_total) over
//   the whole brace (end zones included); the casing's tube stays straight. The buckling-mode
//   shape is refused (it needs the reduced model's eigen-analysis).
// - Stations: each zone (connection, transition outside the casing, overlap, half yielding
//   length) is divided into ceil(length / axial_element_size) equal elements.
//
// Errors (ParameterError, field = the brace file's JSON path below the root, e.g.
// "solid/elements_across_core"): bad densities, mass scaling or threads; gap < 0; fewer than
// 2 elements across the core's smaller side or through the mortar; a cruciform arm shorter
// than one element; no room for mortar; an element of aspect ratio (longest / shortest mean
// edge) over 20.
#pragma once

#include "brb/model/brace_spec.hpp"
#include "brb/solid/hex_mesh.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>
#include <vector>

namespace brb::solid {

/// A quad face: 4 global node indices, counter-clockwise seen from outside its own body.
using QuadFace = std::array<int, 4>;

/// A part's mesh: local nodes (columns) and elements; global_nodes[n] is local node n's
/// global index. Empty (no elements) when the part is absent.
struct BracePartMesh {
  std::string name;
  HexMesh mesh;
  std::vector<int> global_nodes;
  bool empty() const { return mesh.elements.empty(); }
};

/// Largest element aspect ratio the mesher accepts (longest / shortest mean edge).
inline constexpr double kMaxElementAspectRatio = 20.0;

struct BraceMesh {
  Eigen::Matrix3Xd nodes;             ///< global reference coordinates (mm)
  BracePartMesh core;                 ///< core steel with its end zones
  BracePartMesh mortar;               ///< mortar fill (with the homogenised tube when so chosen)
  BracePartMesh tube;                 ///< steel tube (empty: homogenised or mortar-only casing)
  std::vector<QuadFace> core_faces;   ///< core faces across the gap from the casing
  std::vector<QuadFace> casing_faces; ///< mortar faces around the opening
  std::vector<int> loaded_end;        ///< core nodes of the driven end (x = L_total)
  std::vector<int> fixed_end;         ///< core nodes of the start (x = 0); empty in a half model
  std::vector<int> symmetry_plane;    ///< all nodes at mid-length; half model only
  std::vector<int> stopper_core;      ///< core nodes of the stopper station (full model)
  std::vector<int> stopper_casing;    ///< casing nodes of the stopper station (full model)
  bool half_length = false;
  double x_start = 0.0, x_end = 0.0;           ///< meshed extent along x (mm)
  double casing_start = 0.0, casing_end = 0.0; ///< the casing's extent (mm; equal: no casing)
  double core_area = 0.0;                      ///< area of the meshed core section (mm^2)
  double stopper_stiffness = 0.0;              ///< N/mm (full model with a casing)
  std::vector<double> stations;                ///< x of the core stations
};

/// The mesh of the brace. Throws ParameterError (see the header) for a bad spec.
BraceMesh mesh_brace(const model::BraceSpec& brace, const model::SolidMeshSpec& solid);

/// Checks the solid block against the brace by meshing it (the brace reader's check):
/// throws what mesh_brace throws.
void validate_brace_mesh(const model::BraceSpec& brace, const model::SolidMeshSpec& solid);

/// Area and second moments of a section's exact outline (mm^2, mm^4): I_y = int z^2 dA,
/// I_z = int y^2 dA.
struct SectionProperties {
  double area = 0.0, second_moment_y = 0.0, second_moment_z = 0.0;
};
SectionProperties exact_section_properties(const model::SectionSpec& section);

} // namespace brb::solid
