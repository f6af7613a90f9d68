// BraceSpec: what a brace is, as the user describes it (the `brb` brace schema of the
// README), independent of how it is read. Units: mm, N, MPa.
//
// Geometry along the brace axis (global x), symmetric about mid-length:
//   connection | transition | yielding core | transition | connection
// The casing (issue "BRB element") is optional: `casing == nullopt` is the bare core.
#pragma once

#include "brb/element/beam_integration.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_parameters.hpp"
#include "brb/section/fiber_layout.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

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

/// The casing around the yielding core (DESIGN.md section 4, "expanded" form): a steel
/// tube filled with mortar, spanning the yielding length, linked to the core at every core
/// station by a CasingContact and tied to it by a stopper (axial and twist), by default at
/// mid-length.
///
/// Mortar fill (a simplification, stated): the tube's inside minus an opening around the
/// core. Circular tube (round core only): a circular ring from the tube's inner diameter
/// down to core diameter + 2 gap. Rectangular tube (any core): a rectangular ring from the
/// tube's inner size down to the core's bounding box + 2 gaps per direction; the mortar
/// that fills the re-entrant corners of a cruciform core is left out.
struct CasingSpec {
  /// rectangular_tube or circular_tube. Without a steel tube (`steel_tube` false) it is the
  /// outline of a mortar-only casing (wall 0), as in the thesis's small BRB
  /// (BRB_SOURCE_FACTS section 6: a 30 x 30 mm mortar casing).
  SectionSpec tube;
  bool steel_tube = true;
  material::SteelParameters tube_steel;
  material::MortarParameters mortar;
  /// Fibers of the mortar fill: through its thickness and around it (circular ring:
  /// rings x sectors; rectangular ring: through x along each side).
  int fill_fibers_a = 3, fill_fibers_b = 16;
  double gap_y = 0.0; ///< clearance per side along y (mm)
  double gap_z = 0.0; ///< clearance per side along z (mm)
  /// Coulomb coefficient of the core-casing interface (BRB_SOURCE_FACTS section 4: 0.1).
  double friction_coefficient = 0.1;
  /// nu_c of the core's lateral expansion in the contact links (element::CoreExpansion):
  /// lateral over axial strain, 0.5 for plastic incompressibility; 0 (the default): the core
  /// keeps its size (two-node links that see only the core's lateral motion). Off by default
  /// while the solver's path through the mode jumps is not robust to it (README, "Core expansion is
  /// opt-in"): on Girona D1 with 8 elements, nu_c = 0.5 sends a bowed core onto a branch
  /// that punches a bearing face through at 0.75 d_y, where nu_c = 0 and 1e-9 do not.
  double core_expansion = 0.0;
  /// A mortar-only casing splits (element::CasingSplitting): the core pressing its faces
  /// pulls the mortar walls beside its opening apart (tension cracking at f_t, far below the
  /// bearing's crushing). Opt-in (default false) while the solver cannot follow the collapse
  /// it leads to (README, "Casing splitting"); a steel tube casing never splits (the tube holds).
  bool splitting = false;
  /// Sub-element high-mode waves (element::HighModeWaves): the friction of the core's
  /// buckling waves shorter than two core elements. The value is the crest factor c (4: the
  /// half-wave's moment equilibrium, kDefaultCrestFactor); absent (the default): off.
  std::optional<double> high_mode_waves;
  static constexpr double kDefaultCrestFactor = 4.0;
  /// Unbonding-layer spring per unit length of core (N/mm per mm), always active in both
  /// transverse directions. Absent: kDefaultLayerRatio times the mortar's bearing stiffness
  /// per unit length, E_mortar x (core extent) / (mortar thickness).
  std::optional<double> layer_stiffness;
  /// Default layer stiffness relative to the bearing stiffness per unit length. Small on
  /// purpose: the layer only keeps the floating casing stable while the gaps are open. As
  /// an elastic foundation beta under the core it raises the core's buckling load to at
  /// most 2 sqrt(beta E I) (long-column limit): 9 kN for the Girona D3 core (beta = 0.0088
  /// N/mm^2), under 10 % of its yield force, against a bearing stiffness 1e6 times higher.
  static constexpr double kDefaultLayerRatio = 1e-6;
  /// Stick penalty of the axial friction relative to the bearing stiffness of the station
  /// (stiff: the elastic slip before sliding is 1/100 of the bearing's elastic penetration).
  double tangential_stiffness_ratio = 100.0;
  /// Stopper stiffness relative to the core's E A / L_y (axial) and G J / L_y (twist).
  double stopper_stiffness_ratio = 1e3;
  /// Where the stopper ties core and casing: a fraction of the casing's length from its
  /// start, in [0, 1]; it goes to the station nearest that point (0.5: mid-length).
  double stopper_position = 0.5;
  /// Length of each transition zone that lies inside the casing, from the yielding core
  /// outward (mm, 0 <= overlap <= transition length; default 0: the casing spans the
  /// yielding length only). Real BRBs insert the stiffer transition into the casing so that
  /// the core cannot hinge where it leaves the casing (the end-zone mechanism of a pinned
  /// brace with long end zones). The overlap gets its own elements and contact stations,
  /// with the same clearances around the transition's section.
  double overlap = 0.0;

  /// The mortar fill's fiber layout around a core of the given section.
  section::FiberLayout fill_mesh(const SectionSpec& core) const;
  /// Clear mortar thickness between the core's opening and the tube in y and z (mm).
  std::pair<double, double> mortar_thickness(const SectionSpec& core) const;
};

/// Extent of a core section along section y and z (its bounding box, mm).
std::pair<double, double> core_extent(const SectionSpec& core);

/// How a brace enters a model (DESIGN.md section 4, BRB element): `full` is the fiber core
/// with its casing, `truss` a co-rotational truss with the core's uniaxial steel law in
/// series with the elastic end zones (element::BraceTruss). A full brace is `condensed`
/// (its internal model solved inside the element, analysis::BRBElement) or `expanded` (its
/// internal nodes and elements join the model, add_brace_to_model).
enum class Fidelity { full, truss };
enum class ElementMode { condensed, expanded };
struct ElementSpec {
  Fidelity fidelity = Fidelity::full;
  ElementMode mode = ElementMode::condensed;
};

/// How the casing's steel tube enters the 3D continuum mesh (solid::mesh_brace): as its own
/// steel elements, or homogenised into the mortar with n_E = E_s / E_c as the source did
/// (BRB_SOURCE_FACTS section 7).
enum class SolidTube { elements, homogenised };

/// How the 3D model holds the core's end faces sideways. centre_lines: u_y on the face's
/// nodes on its centre line along z, u_z on those on its centre line along y, so the face
/// neither moves sideways nor twists but its section contracts and expands freely (the
/// uniaxial stress of the fiber model up to the end); clamped: every node's u_y and u_z (the
/// grips of a test machine, which restrain the Poisson strain there and stiffen a stubby core).
/// In both the whole face is held (driven) along x, so it cannot rotate: the 3D core's ends
/// are fixed in bending. pinned: held sideways as centre_lines, and the face stays plane but
/// rotates freely about y and z through its centre (a rigid end plate on a spherical pin,
/// solid_explicit.hpp's PivotingFace): the reduced model's "ends": "pinned".
enum class SolidEndFaces { centre_lines, clamped, pinned };

/// The brace schema's names of SolidEndFaces (the solid block's `end_faces`): read by
/// io::read_brace, written back by end_faces_name (brb solid's summary).
inline constexpr std::array<std::pair<std::string_view, SolidEndFaces>, 3> kSolidEndFacesNames{
    {{"centre_lines", SolidEndFaces::centre_lines},
     {"clamped", SolidEndFaces::clamped},
     {"pinned", SolidEndFaces::pinned}}};

/// The schema's name of an end-face support ("centre_lines", "clamped" or "pinned").
std::string_view end_faces_name(SolidEndFaces faces);

/// How the 3D model's hourglass stiffness follows the law (solid::HourglassControl):
/// elastic: the elastic moduli throughout (stored hourglass energy); tangent: scaled by each
/// element's ratio of its law's response to the elastic one over its last step, so a
/// yielding element's in-element bending follows about E_t instead of E.
enum class SolidHourglass { elastic, tangent };

/// The brace schema's names of SolidHourglass (the solid block's `hourglass`).
inline constexpr std::array<std::pair<std::string_view, SolidHourglass>, 2> kSolidHourglassNames{
    {{"elastic", SolidHourglass::elastic}, {"tangent", SolidHourglass::tangent}}};

/// The schema's name of a hourglass control ("elastic" or "tangent").
std::string_view hourglass_name(SolidHourglass hourglass);

/// The `solid` block of a brace file: the 3D continuum mesh of the brace (issue 6;
/// solid/brace_mesh.hpp states the geometry). Defaults as listed.
struct SolidMeshSpec {
  int elements_across_core = 2; ///< across the core's smaller side (>= 2)
  double axial_element_size =
      0.0; ///< target element length along the axis (mm); 0: 3 x the core's element size across
  int elements_through_mortar = 2; ///< through the mortar's thickness (>= 2)
  bool half_length = false;        ///< mid-length to the driven end, symmetry plane at mid-length
  SolidTube tube = SolidTube::elements;
  SolidEndFaces end_faces = SolidEndFaces::centre_lines;
  double steel_density = 7.85e-9;  ///< tonne/mm^3 (the source's 7850 kg/m^3)
  double mortar_density = 2.35e-9; ///< tonne/mm^3 (the source's 2350 kg/m^3)
  double mass_scaling = 1.0;       ///< factor on both densities (>= 1: a longer stable step)
  int threads = 1;                 ///< threads of the element loops
  SolidHourglass hourglass = SolidHourglass::elastic;
  double hourglass_min_scale = 0.05; ///< floor of the tangent form's scale, in (0, 1]
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
  std::optional<CasingSpec> casing;   ///< nullopt: bare core
  ElementSpec element;                ///< fidelity and mode in frames (brace file: "element")
  std::optional<SolidMeshSpec> solid; ///< the 3D continuum mesh (brace file: "solid")

  /// Length between the outer nodes (work points), mm.
  double total_length() const;
};

} // namespace brb::model
