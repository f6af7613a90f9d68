// CompositeSection: two sections at the same point add up.
#include "brb/section/composite_section.hpp"

#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <gtest/gtest.h>

namespace brb::section {
namespace {

TEST(CompositeSection, SumsResponsesEnergiesAndTorsionOfItsParts) {
  // Reference: the parts share the plane-section deformation, so every resultant and
  // energy of the composite is the sum of the parts' evaluated separately.
  material::SteelParameters steel;
  steel.youngs_modulus = 210000.0;
  steel.yield_stress = 275.0;
  steel.kinematic_hardening = 2100.0;
  const material::MortarParameters mortar{17520.0, 0.2, 50.0, 5.0, 0.1};
  const FiberLayout tube = mesh_circular_tube(115.0, 3.0, 2, 24);
  const FiberLayout fill = mesh_circular_tube(109.0, 42.5, 3, 16);
  FiberSection<material::SteelUniaxial> steel_alone(tube, material::SteelUniaxial(steel, 100.0),
                                                    80769.0);
  FiberSection<material::MortarUniaxial> mortar_alone(fill, material::MortarUniaxial(mortar, 100.0),
                                                      7300.0);
  CompositeSection composite(steel_alone, mortar_alone);

  // tension on one side cracks the mortar, the other side stays elastic
  const SectionVector deformation(1e-4, 4e-6, -1e-6);
  const SectionResponse sum = composite.evaluate(deformation);
  const SectionResponse a = steel_alone.evaluate(deformation);
  const SectionResponse b = mortar_alone.evaluate(deformation);
  EXPECT_LT((sum.force - a.force - b.force).norm(), 1e-9 * a.force.norm());
  EXPECT_LT((sum.tangent - a.tangent - b.tangent).norm(), 1e-9 * a.tangent.norm());
  EXPECT_GT(composite.max_damage(), 0.0); // mortar fibers past ft = 5 MPa (strain 2.9e-4)
  EXPECT_DOUBLE_EQ(composite.max_damage(), mortar_alone.max_damage());
  EXPECT_NEAR(composite.stored_energy(), steel_alone.stored_energy() + mortar_alone.stored_energy(),
              1e-9);
  EXPECT_NEAR(composite.dissipated_energy(),
              steel_alone.dissipated_energy() + mortar_alone.dissipated_energy(), 1e-12);
  EXPECT_DOUBLE_EQ(composite.torsional_stiffness(),
                   steel_alone.torsional_stiffness() + mortar_alone.torsional_stiffness());

  // revert forgets the trial damage; commit keeps it
  composite.revert_to_committed();
  composite.evaluate(SectionVector::Zero());
  EXPECT_DOUBLE_EQ(composite.max_damage(), 0.0);
  composite.evaluate(deformation);
  composite.commit();
  composite.evaluate(SectionVector::Zero());
  EXPECT_GT(composite.max_damage(), 0.0);
}

} // namespace
} // namespace brb::section
