// A cyclic run of the 3D continuum brace (issue 6): builds the SolidBody of a brace
// (brace_mesh.hpp: core steel, mortar, tube, stopper tie, contact from a factory), drives the
// loaded end through a protocol of brace elongations with explicit central differences
// (solid_explicit.hpp) and records, per output step, the deformation, the axial force and
// the energies.
//
// Set-up (stated):
// - Laws: core and end zones material::SteelDamagePlasticity3D(brace.steel), mortar
//   material::MortarDamage3D(casing.mortar), tube SteelDamagePlasticity3D(casing.tube_steel);
//   the characteristic length of each element is V^(1/3) (SolidModel). Densities of the solid
//   block times its mass scaling.
// - Supports: full length: the start face (core, x = 0) has u_x = 0 and the driven face
//   (core, x = L) follows u_x = d(t); sideways both are held as the solid block's `end_faces`
//   says (model::SolidEndFaces): by default on their centre lines only (no sideways motion or
//   twist, the section's Poisson strain free, as in the fiber model's uniaxial stress), or
//   clamped (u_y = u_z = 0 on every node: the grips of a test machine, which stiffen a stubby
//   core: the small BRB of the source, 100 mm long and 10 mm wide, by 13 % at 15 d_y with two
//   elements across). Held along x over their whole area, those faces cannot rotate: the
//   core's ends are fixed in bending. `end_faces` "pinned": sideways as the centre lines, and
//   each face stays plane but pivots about its centre (PivotingFace of solid_explicit.hpp; the
//   driven face's translation is d(t)): the reduced model's pinned ends. The casing is held
//   only by the stopper tie and the contact. Half length
//   (the source's half model, BRB_SOURCE_FACTS section 7): u_x = 0 on the symmetry plane
//   (core, mortar, tube at mid-length), the driven face follows u_x = d(t) / 2; the brace
//   elongation reported is twice the driven face's displacement.
// - Loading: the protocol's targets d_1, d_2, ... from d_0 = 0, each excursion (the points from
//   one reversal to the next, in one direction) a smooth 1 - cos ramp (smooth_ramp: zero
//   velocity at both ends) of duration time_per_deformation x |excursion| (at least
//   min_excursion_time, when given), passing the points
//   inside it without stopping; records at equal times between the moments it passes them.
//   Default time_per_deformation: 20 T_1 / d_y, with T_1 = 4 L / sqrt(E / rho) the first
//   axial period of the isolated core clamped at one end and free at the other (L: the whole
//   brace length, also in a half model, so both load at the same rate; rho: the physical
//   density, so that mass scaling s lengthens the stable step by sqrt(s) and shortens the run
//   by as much, at inertia forces s times larger: watch KE / IE) and
//   d_y = f_y L_y / E: a ramp of one yield deformation lasts twenty core periods (the source chose
//   its loading periods from the core's modal periods, section 5; the 20-period ramp keeps KE < 5 %
//   of IE in the quasi-static bar test of solid_explicit_test).
// - Force: the sum of the x forces (elements + interactions) on the driven face's nodes: the
//   reaction that the machine applies.
#pragma once

#include "brb/model/brace_spec.hpp"
#include "brb/solid/brace_mesh.hpp"
#include "brb/solid/solid_interaction.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace brb::solid {

/// Builds the core-casing contact from the core's faces, the casing's faces (QuadFace: global
/// nodes, counter-clockwise seen from outside their own body) and the global reference
/// coordinates. Null: no contact.
using ContactFactory = std::function<std::unique_ptr<SolidInteraction>(
    const std::vector<QuadFace>& core_faces, const std::vector<QuadFace>& casing_faces,
    const Eigen::Matrix3Xd& coordinates)>;

struct SolidBraceRunSettings {
  /// s per mm of brace elongation (> 0), or 0: the default of the header.
  double time_per_deformation = 0.0;
  /// Total duration of the protocol (s, > 0); overrides time_per_deformation when given.
  double duration = 0.0;
  /// Shortest duration of an excursion (s, >= 0; 0: none): a floor on the ramp time of the
  /// small first cycles, slowing them where the internal energy is still small. Not with a
  /// duration (the floor would lengthen the protocol past it).
  double min_excursion_time = 0.0;
  int outputs_per_segment = 20;    ///< records per protocol segment (>= 1)
  double stable_step_safety = 0.9; ///< on the body's stable step
  /// alpha (1/s, >= 0; 0: none) of a mass-proportional damping of the nodes' lateral (y, z)
  /// motion (solid_explicit.hpp): it calms a dynamic snap (global buckling, loose pieces of
  /// split mortar) without resisting the axial loading; its work is the records' `damping`.
  double lateral_damping = 0.0;
};

/// One output step.
struct SolidBraceRecord {
  /// The protocol point the record's segment leads to (1-based; 0: the initial state).
  int point = 0;
  long steps = 0;                                        ///< explicit steps up to the record
  double time = 0.0;                                     ///< s
  double deformation = 0.0;                              ///< brace elongation (mm)
  double force = 0.0;                                    ///< axial force, tension positive (N)
  double kinetic = 0.0, internal = 0.0, hourglass = 0.0; ///< N mm
  double contact_stored = 0.0; ///< energy stored in the interactions' springs (N mm)
  double friction = 0.0;       ///< energy dissipated by friction (N mm)
  double damping = 0.0;        ///< energy dissipated by the lateral damping (N mm)
  double external = 0.0;       ///< work of the driven face (N mm)
  double energy_error = 0.0;   ///< SolidExplicitEnergy::relative_error
};

struct SolidBraceRun {
  std::vector<SolidBraceRecord> records;
  bool completed = false;
  std::string failure;    ///< why the run stopped early
  double time_step = 0.0; ///< s
  long steps = 0;
  int nodes = 0, elements = 0;
  double first_axial_period = 0.0;   ///< T_1 of the header (s)
  double time_per_deformation = 0.0; ///< s/mm used
  double min_excursion_time = 0.0;   ///< s used (0: none)
  double lateral_damping = 0.0;      ///< 1/s used (0: none)
};

class SolidBody;

/// The state of the run at an output step, for recorders (field snapshots, indicators): the
/// body (parts, interactions and their committed states), its mesh, the global displacement
/// vector (mm) and the record just made.
struct SolidBraceState {
  const SolidBody& body;
  const BraceMesh& mesh;
  const Eigen::VectorXd& displacement;
  const SolidBraceRecord& record;
};
using SolidBraceObserver = std::function<void(const SolidBraceState&)>;

/// The first axial period T_1 = 4 L / sqrt(E / rho) of the isolated core (header).
double core_first_axial_period(const model::BraceSpec& brace, const model::SolidMeshSpec& solid);

/// Runs the brace through `deformations` (mm, brace elongation targets from 0). The solid block
/// is brace.solid (defaults when absent). Throws ParameterError / std::invalid_argument for a
/// bad spec or settings; a failed integration returns completed = false with the records so
/// far.
SolidBraceRun run_solid_brace(const model::BraceSpec& brace,
                              const std::vector<double>& deformations,
                              const SolidBraceRunSettings& settings = {},
                              const ContactFactory& contact = nullptr,
                              const SolidBraceObserver& observer = nullptr);

} // namespace brb::solid
