// The finite element model of a brace from its BraceSpec: a chain of co-rotational fiber
// beams along global x (connection, transition, yielding core, transition, connection),
// with the initial imperfection, end conditions, and the brace's nominal yield force and
// yield deformation. Section axes: y along global Y, z along global Z.
//
// With a casing (BraceSpec::casing, DESIGN.md section 4, "expanded" form: every internal
// node in the global system): casing nodes at the core stations of the yielding zone
// (straight, on the brace axis), co-rotational casing beams whose sections are the tube's
// steel fibers plus the mortar fill's fibers, a CasingContact between the core node and the
// casing node at every such station, and a ZeroLengthSpring stopper (ux, rx) at the station
// nearest CasingSpec::stopper_position (mid-length by default). The casing has no other support.
#pragma once

#include "brb/element/brace_truss.hpp"
#include "brb/element/casing_contact.hpp"
#include "brb/element/corot_beam_3d.hpp"
#include "brb/element/zero_length_spring.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_uniaxial.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/model/model.hpp"
#include "brb/model/work_skips.hpp"
#include "brb/section/composite_section.hpp"
#include "brb/section/fiber_section.hpp"

#include <optional>

#include <string>
#include <vector>

namespace brb::model {

using CoreSection = section::FiberSection<material::SteelUniaxial>;
using CoreBeam = element::CorotBeam3D<CoreSection>;
using CasingSection = section::CompositeSection<section::FiberSection<material::SteelUniaxial>,
                                                section::FiberSection<material::MortarUniaxial>>;
using CasingBeam = element::CorotBeam3D<CasingSection>;

/// The casing's part of a brace model (element pointers are owned by the Model).
struct CasingModel {
  std::vector<int> nodes;                         ///< casing nodes from start to end (its stations)
  std::vector<int> core_nodes;                    ///< the core node at each casing station
  std::vector<double> tributary_length;           ///< per station (mm)
  std::vector<CasingBeam*> beams;                 ///< casing elements from start to end
  std::vector<element::CasingContact*> contacts;  ///< one per station
  element::ZeroLengthSpring* stopper = nullptr;   ///< core-casing tie (stopper)
  std::size_t stopper_station = 0;                ///< index into nodes
  element::CasingContactParameters interior_link; ///< link parameters of an interior station
  element::SpringStiffness stopper_stiffness{};
  /// false for a mortar-only casing (CasingSpec::steel_tube): its fill fibers are the casing
  bool steel_tube = true;
};

/// Where a brace lies: the start node's position and the axes (columns: brace axis from
/// start to end, section y, section z), global.
struct BracePlacement {
  Vector3 origin = Vector3::Zero();
  element::Matrix3 axes = element::Matrix3::Identity();

  /// The placement between two points; the section's z axis is `section_z` made
  /// orthogonal to the axis (default: global Z, or global Y for a brace along Z).
  /// Throws ParameterError when the points coincide or section_z is along the axis.
  static BracePlacement between(const Vector3& start, const Vector3& end,
                                std::optional<Vector3> section_z = std::nullopt);
};

/// A brace placed in a model: its nodes and elements (owned by the Model) and its nominal
/// properties.
struct BraceHandles {
  Vector3 origin = Vector3::Zero();                     ///< position of the start node
  element::Matrix3 axes = element::Matrix3::Identity(); ///< axis, section y, section z
  int start_node = 0;                                   ///< start outer node (work point)
  int end_node = 0;                                     ///< end outer node
  std::vector<int> nodes;                               ///< all nodes from start to end
  std::vector<CoreBeam*> beams;                         ///< all elements from start to end
  std::vector<bool> in_yielding_zone;                   ///< per element
  double core_area = 0.0;                               ///< mm^2
  double yield_force = 0.0;                             ///< fy A_core (N)
  /// Axial deformation between the outer nodes at first yield of the core (mm): the series
  /// flexibility of the zones, P_y sum L / (E A).
  double yield_deformation = 0.0;
  std::optional<CasingModel> casing;    ///< present when the spec has a casing
  element::BraceTruss* truss = nullptr; ///< the `truss` fidelity's element (then no beams)
  /// Things the user should know, said once each (e.g. a damage onset stress lowered because
  /// the elements are too long for the softening, DESIGN.md section 3).
  std::vector<std::string> warnings;
};

/// The stand-alone brace along global x (the set-up of a cyclic test): the start node is
/// held (ux, uy, uz, rx; all six for fixed ends), the end node moves along x only (uy, uz
/// held; rx, ry, rz too for fixed ends): its x displacement is the deformation.
struct BraceModel : BraceHandles {
  Model model;
};

/// Builds the model of the brace, with its casing when spec.casing is set. Throws
/// ParameterError (with the key of the brace schema) on inconsistent geometry. `skips`: the
/// element- and material-level switches of WorkSkips (open links, elastic fast path).
BraceModel build_brace_model(const BraceSpec& spec, const WorkSkips& skips = {});

/// The `expanded` BRB element (DESIGN.md section 4): the brace's internal nodes and elements
/// join `model` between two of its nodes, which must be the brace's length apart; the section
/// z axis (and a "z" imperfection) points along `section_z` made orthogonal to the axis
/// (default: see BracePlacement::between). No fixity is added: the model's supports and
/// the elements around the brace hold it. Throws ParameterError (key under "element/").

/// Lateral offsets (global Y, Z per node, mm) of the first elastic buckling mode of the
/// perfect bare core (any casing left out), scaled so that the largest lateral offset is 1 mm.
std::vector<std::pair<double, double>> first_buckling_mode(const BraceSpec& spec);

/// The `truss` fidelity of the brace (element::BraceTruss): its core area, yielding length,
/// steel, and the flexibility of the connection and transition zones at both ends.
element::BraceTrussParameters truss_parameters(const BraceSpec& spec);

/// The supports of a stand-alone brace along global x (the test set-up of `brb cyclic`): the
/// start node held (ux uy uz rx), the end node free only along x and in its rotations about
/// y and z (uy uz held); with fixed ends every rotation held too. Shared by build_brace_model
/// and analysis::build_condensed_brace_model, so both hold a brace alike.
void hold_stand_alone_ends(Model& model, int start_node, int end_node, EndCondition ends);

/// The stand-alone brace as one BraceTruss along global x, with the supports of
/// build_brace_model (every rotation held: the truss carries none). `nodes` = the two
/// outer nodes; no beams, no casing.
BraceModel build_brace_truss_model(const BraceSpec& spec, const WorkSkips& skips = {});

BraceHandles add_brace_to_model(Model& model, const BraceSpec& spec, int start_node, int end_node,
                                std::optional<Vector3> section_z = std::nullopt,
                                const WorkSkips& skips = {});

} // namespace brb::model
