// The source's mortar prism verification (BRB_SOURCE_FACTS section 6; issue 6 acceptance):
// pulled to 0.8 mm, a 100 x 100 x 500 mm mortar prism of hexahedra softens in one band of
// elements and dissipates the fracture energy Gf per unit area of the band (lc = V^(1/3)
// regularises the law). Explicit path: Newton under displacement control loses the path at
// the peak, where the band's corners soften first.
#include "brb/material/mortar_damage.hpp"
#include "brb/solid/solid_explicit.hpp"

#include "support/mortar_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace brb::solid {
namespace {

TEST(SolidMortarPrism, TensionSofteningDissipatesTheFractureEnergyOfOneBand) {
  // Mortar of the source's prism: E 17520 MPa, nu 0.2, fc 10 MPa, ft 1 MPa, rho 2350 kg/m^3;
  // its Gf is not given, we take 0.1 N/mm (no snap-back: the bar stores L ft^2 / (2 E) =
  // 0.014 N/mm of area at the peak, less than Gf). 2 x 2 x 10 cubes of 50 mm; the two node
  // planes of the middle layer (x = 250 and 300 mm) are shrunk by 1 % across, so that layer
  // reaches ft first and localises. Explicit, as the source: the x_max face is pulled to
  // 0.8 mm by a 1 - cos ramp over 0.05 s (about 70 first-mode periods).
  // Reference: the band dissipates Gf x its area (Oliver et al. 1990 regularisation, which
  // holds when lc = V^(1/3) equals the band width: cubes); acceptance of issue 6: within 5 %.
  const material::MortarParameters mortar = test::prism_mortar();
  const double side = 100.0, length = 500.0, shrink = 0.99, duration = 0.05;
  const StructuredPrismMesh prism(Eigen::Vector3d(length, side, side), {10, 2, 2});
  HexMesh mesh = prism.mesh();
  for (int n = 0; n < mesh.node_count(); ++n) {
    const double x = mesh.nodes(0, n);
    if (std::abs(x - 250.0) < 1e-9 || std::abs(x - 300.0) < 1e-9) {
      mesh.nodes(1, n) = 0.5 * side + shrink * (mesh.nodes(1, n) - 0.5 * side);
      mesh.nodes(2, n) = 0.5 * side + shrink * (mesh.nodes(2, n) - 0.5 * side);
    }
  }
  SolidModel<material::MortarDamage3D> model(
      mesh,
      [&](double lc) {
        return material::MortarDamage3D(mortar, lc, material::LongElementRule::reject);
      },
      2.35e-9);
  SolidLoading loading;
  for (int n : prism.face_nodes(PrismFace::x_min))
    loading.prescribed.add(n, 0, 0.0);
  for (int n : prism.face_nodes(PrismFace::x_max))
    loading.prescribed.add(n, 0, 0.8);
  loading.prescribed.add(prism.node_index(0, 0, 0), 1, 0.0);
  loading.prescribed.add(prism.node_index(0, 0, 0), 2, 0.0);
  loading.prescribed.add(prism.node_index(0, 2, 0), 2, 0.0);
  loading.history = [=](double t) { return smooth_ramp(t, duration); };
  SolidExplicit<material::MortarDamage3D> solver(model, loading);
  std::string failure;
  double peak = 0.0, worst_balance = 0.0, worst_hourglass = 0.0;
  const int outputs = 400;
  for (int k = 1; k <= outputs; ++k) {
    ASSERT_TRUE(solver.run_to(duration * k / outputs, failure)) << failure;
    double force = 0.0;
    for (int n : prism.face_nodes(PrismFace::x_max))
      force += solver.internal_force()[3 * n];
    peak = std::max(peak, force);
    const SolidExplicitEnergy& e = solver.energy();
    worst_balance = std::max(worst_balance, e.relative_error());
    worst_hourglass = std::max(worst_hourglass, e.hourglass / e.internal);
  }
  // dissipated energy and where: only the middle layer (i = 5) may be damaged through
  double dissipated = 0.0;
  for (int e = 0; e < model.element_count(); ++e) {
    dissipated += model.states()[e].dissipated_energy * model.references()[e].volume;
    if (e % 10 != 5)
      EXPECT_LT(model.states()[e].damage, 0.5) << "element " << e << " outside the band";
    else
      EXPECT_GT(model.states()[e].damage, 0.99) << "element " << e << " in the band";
  }
  const double band_area = shrink * shrink * side * side;
  RecordProperty("dissipated_over_gf_area",
                 std::to_string(dissipated / (mortar.fracture_energy * band_area)));
  RecordProperty("peak_over_ft_area", std::to_string(peak / band_area));
  RecordProperty("max_energy_error", std::to_string(worst_balance));
  RecordProperty("max_hourglass_over_internal", std::to_string(worst_hourglass));
  RecordProperty("steps", std::to_string(solver.steps()));
  EXPECT_NEAR(dissipated / (mortar.fracture_energy * band_area), 1.0, 0.05);
  EXPECT_NEAR(peak / (mortar.tensile_strength * band_area), 1.0, 0.05); // where it breaks
  EXPECT_LT(worst_balance, 0.02);
  EXPECT_LT(worst_hourglass, 0.05);
}

} // namespace
} // namespace brb::solid
