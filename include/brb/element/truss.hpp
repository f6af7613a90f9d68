// Truss: the frame's co-rotational truss (DESIGN.md section 4: `Truss`, e.g. a leaning column's
// link or a brace modelled as a bar). It is CorotTruss (corot_truss.hpp: exact large rotations,
// N = A sigma((l - L0) / L0), force and tangent from chord_force_and_tangent) with the law
// chosen at construction among UniaxialLaw's (elastic, steel, mortar). One material point over
// the whole length: the law's characteristic length is L0 (make_truss does that).
// Energies come from the law: stored = A L0 psi(eps), dissipated = A L0 D.
// Rotations carry nothing: nodes joined only by trusses need their rotations held.
#pragma once

#include "brb/element/corot_truss.hpp"
#include "brb/element/uniaxial_law.hpp"

namespace brb::element {

using Truss = CorotTruss<UniaxialLaw>;

} // namespace brb::element
