// A virtual cyclic test of the 3D continuum brace (`brb solid`, issue 6): the explicit run of
// brace_run.hpp with the core-casing contact of the source (node_to_surface_contact.hpp),
// reported in the result type of the reduced-order test (analysis::CyclicTestResult), so the
// 3D and the reduced model write the same hysteresis.csv and summary.json and are compared by
// the same code.
//
// Contact (BRB_SOURCE_FACTS section 4): the core is the master surface, the mortar's faces
// around the opening the slave one, with the two-pass option (each surface also master of the
// other's nodes), so that neither the core's edges nor the mortar's can pass through the other
// surface; kappa is the casing's friction coefficient. Normal penalty per unit area: E_c / h,
// h the mortar element's thickness across the ring (the contact adds the compliance of one more
// mortar layer: about 0.01 mm at a bearing stress of 40 MPa on the small BRB, against its
// 0.05 mm clearance); tangential stiffness the same (ratio 1). Search distance: the gap plus
// the core element's size across, so a node is seen well before it closes the gap.
//
// Indicators (analysis::BraceIndicators, the reduced model's names; rules stated here):
// - max_steel_damage, core_fracture (damage >= kFractureDamage): over the core's elements;
// - max_mortar_damage, min_fill_residual_strength: over the mortar's elements;
//   max_bearing_damage, min_bearing_residual_strength: over the mortar elements that bound the
//   opening (one of its faces is a contact face of the casing); casing_failure: the residual
//   strength of one of those fell to kCrushedResidualStrength (0.1 of its onset stress), the
//   reduced model's rule for the mortar under a station, taken to the elements that bear on
//   the core. Each element's residual strength uses its own law (lc = V^(1/3)), so a crack
//   counts at the same opening as in the reduced model's faces and walls;
// - lateral displacements: the largest sqrt(u_y^2 + u_z^2) of a core node and of a casing
//   node; global_buckling: the casing's lateral displacement exceeded L_y / 250 less the
//   clearance (the first half of the reduced model's rule; the second half, the bow growing
//   by more than the shortening over a step, is not applied: stated as a difference);
// - cumulative_inelastic_deformation: analysis::inelastic_deformation_increment over records;
// - max_buckling_half_waves: not measured (0).
// The indicators after every output record are kept as the cyclic test's history
// (`brb solid --histories` writes them as element_history.csv): there the core strain is the
// brace's deformation over its yielding length and the dissipated energy the energy balance's.
#pragma once

#include "brb/analysis/cyclic_test.hpp"
#include "brb/model/brace_spec.hpp"
#include "brb/solid/brace_run.hpp"

#include <span>
#include <string>
#include <vector>

namespace brb::solid {

struct SolidCyclicSettings {
  SolidBraceRunSettings run;
  /// Normal contact penalty over E_c / h (see the header); > 0.
  double contact_penalty_factor = 1.0;
};

/// The quasi-static checks' floor, as a fraction of P_y d_y / 2 (see SolidCyclicResult).
inline constexpr double kQuasiStaticFloorFraction = 0.01;

struct SolidCyclicResult {
  /// Steps: one per output record (step k: record k; `substeps`: the explicit steps since
  /// the previous record); cycles, peaks and indicators as the reduced-order test.
  analysis::CyclicTestResult cyclic;
  SolidBraceRun run; ///< records with their energies
  /// KE / IE and hourglass / IE are taken over the records whose internal energy IE exceeds
  /// this floor (N mm): kQuasiStaticFloorFraction of the elastic energy at yield, P_y d_y / 2.
  /// Below it the ratio measures the start of the ramp, not the quasi-static state (at t -> 0
  /// KE / IE grows without bound for any loading rate).
  double quasi_static_floor = 0.0;
  double max_kinetic_ratio = 0.0;   ///< largest KE / IE over the records with IE > the floor
  double max_hourglass_ratio = 0.0; ///< largest |hourglass| / IE over the same records
  double max_energy_error = 0.0;    ///< largest relative energy-balance error of a record
  double contact_penalty = 0.0;     ///< N/mm^3 (0: no contact)
};

/// Runs the brace through the protocol: `deformation` (mm, first point 0), `cycle[k]` the full
/// cycle of point k, `cycle_amplitude[c-1]` the amplitude of cycle c (as run_cyclic_test),
/// `yield_force` and `yield_deformation` for the cumulative inelastic deformation. `observer`,
/// when given, also sees every output state (e.g. to write field snapshots). Throws what
/// run_solid_brace throws for a bad spec.
SolidCyclicResult run_solid_cyclic(const model::BraceSpec& brace,
                                   std::span<const double> deformation, std::span<const int> cycle,
                                   std::span<const double> cycle_amplitude, double yield_force,
                                   double yield_deformation, const SolidCyclicSettings& settings,
                                   const SolidBraceObserver& observer = nullptr);

/// Per element of the body's parts, in part order: damage of the steel or mortar law, the
/// equivalent plastic strain (0 for mortar) and the part's index (for field snapshots).
struct SolidElementFields {
  std::vector<double> steel_damage, mortar_damage, plastic_strain, part;
};
SolidElementFields element_fields(const SolidBody& body);

/// Contact pressure at each global node (MPa): the normal force of the node as a slave of the
/// core-casing contact over its tributary area, the larger of its two passes; 0 elsewhere.
std::vector<double> contact_pressure(const SolidBody& body);

} // namespace brb::solid
