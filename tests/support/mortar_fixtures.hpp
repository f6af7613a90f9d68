// Mortar parameters shared by the 3D continuum tests.
#pragma once

#include "brb/material/mortar_damage.hpp"

namespace brb::test {

/// The mortar of the source's prism verification (BRB_SOURCE_FACTS section 6): E 17520 MPa,
/// nu 0.2, fc 10 MPa, ft 1 MPa. Its Gf is not given; 0.1 N/mm is ours (no snap-back in the
/// prism: a 500 mm bar stores L ft^2 / (2 E) = 0.014 N/mm of area at the peak, less than Gf).
inline material::MortarParameters prism_mortar() {
  material::MortarParameters mortar;
  mortar.youngs_modulus = 17520.0;
  mortar.poissons_ratio = 0.2;
  mortar.compressive_strength = 10.0;
  mortar.tensile_strength = 1.0;
  mortar.fracture_energy = 0.1;
  return mortar;
}

} // namespace brb::test
