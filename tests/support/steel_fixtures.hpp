// Steel parameter sets shared by the steel tests.
#pragma once

#include "brb/material/steel_parameters.hpp"

namespace brb::test {

/// S275 of the Girona tests (BRB_SOURCE_FACTS section 7) with mixed linear hardening.
inline material::SteelParameters linear_mixed_steel(double kinematic = 15000.0,
                                                    double isotropic = 6000.0) {
  material::SteelParameters steel;
  steel.youngs_modulus = 210000.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 275.0;
  steel.kinematic_hardening = kinematic;
  steel.isotropic_hardening = isotropic;
  return steel;
}

/// Every hardening mechanism at once: Prager + two Chaboche terms + linear and Voce isotropic.
inline material::SteelParameters chaboche_voce_steel() {
  material::SteelParameters steel = linear_mixed_steel(2000.0, 500.0);
  steel.chaboche = {{12000.0, 120.0}, {3000.0, 15.0}};
  steel.voce_saturation = 40.0;
  steel.voce_rate = 12.0;
  return steel;
}

/// chaboche_voce_steel with ductile damage from fu = 430 MPa (nominal S275 ultimate).
inline material::SteelParameters damaging_steel(double fracture_energy = 60.0) {
  material::SteelParameters steel = chaboche_voce_steel();
  steel.kinematic_hardening = 20000.0; // unbounded hardening drives tau past r0
  steel.damage = material::SteelDamageParameters{430.0, fracture_energy};
  return steel;
}

} // namespace brb::test
