// Sub-element high-mode waves (element::HighModeWaves): the crests' normal force below the
// beam chain's resolution and the friction it adds in a CasingContact.
#include "brb/element/casing_contact.hpp"

#include "support/expansion_probe.hpp"
#include "support/finite_difference.hpp"
#include "support/link_tangent.hpp"

#include <gtest/gtest.h>

#include "brb/material/parameter_error.hpp"
#include "brb/material/steel_uniaxial.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace brb::element {
namespace {

/// Steel with linear kinematic hardening: plastic modulus H, so the tangent past yield is
/// E H / (E + H) (theory of linear hardening).
material::SteelParameters linear_steel() {
  material::SteelParameters steel;
  steel.youngs_modulus = 200000.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 250.0;
  steel.kinematic_hardening = 3000.0;
  return steel;
}

/// A 60 x 10 mm plate (r = 10 / sqrt(12) exactly for a continuous plate; here given), gap 1
/// mm, tributary length 100 mm, elements of 100 mm (l_mesh = 200 mm).
HighModeWaves plate_waves() {
  HighModeWaves waves;
  waves.steel = linear_steel();
  waves.area = 600.0;
  waves.gyration_radius = 10.0 / std::sqrt(12.0);
  waves.thickness = 10.0;
  waves.gap = 1.0;
  waves.tributary_length = 100.0;
  waves.resolved_half_wave = 200.0;
  waves.crest_factor = 4.0;
  return waves;
}

TEST(HighModeWaves, NormalForceIsTheCrestsBearingOfTheUnresolvedWaves) {
  // Reference (theory, written independently of the implementation): the tangent-modulus
  // half-wave l = pi r sqrt(E_t / sigma); each crest bears 4 P g / l and there are h / l of
  // them in the tributary length, so q h = 4 g P h / l^2, less what the beam chain resolves
  // (half-waves down to l_mesh).
  const HighModeWaves waves = plate_waves();
  const double stress = -300.0, tangent = 2000.0;
  const double half_wave = std::numbers::pi * waves.gyration_radius * std::sqrt(tangent / 300.0);
  const double compression = 300.0 * 600.0;
  const double crest = 4.0 * compression * 1.0 / half_wave;
  const double crests = 100.0 / half_wave;
  const double resolved = 4.0 * 1.0 * compression * 100.0 / (200.0 * 200.0);
  const double expected = crest * crests - resolved;
  EXPECT_GT(half_wave, 10.0); // above the thickness cap: the formula, not the cap
  EXPECT_NEAR(waves.normal_force(stress, tangent), expected, 1e-9 * expected);

  // Tension and zero stress: no waves.
  EXPECT_EQ(waves.normal_force(300.0, tangent), 0.0);
  EXPECT_EQ(waves.normal_force(0.0, tangent), 0.0);
  // Elastic compression: l = pi r sqrt(E / sigma) = 458 mm, longer than l_mesh: the beams
  // resolve it, the link adds nothing.
  EXPECT_EQ(waves.normal_force(-200.0, 200000.0), 0.0);
  // A vanishing or negative tangent: the shortest wave, l = the plate's thickness.
  const double shortest = 4.0 * 1.0 * compression * 100.0 * (1.0 / 100.0 - 1.0 / 40000.0);
  EXPECT_NEAR(waves.normal_force(stress, 0.0), shortest, 1e-9 * shortest);
  EXPECT_NEAR(waves.normal_force(stress, -50.0), shortest, 1e-9 * shortest);
  EXPECT_NEAR(waves.normal_force(stress, 1e-6), shortest, 1e-9 * shortest);
  // Linear in the gap and in the crest factor.
  HighModeWaves wider = waves;
  wider.gap = 2.0;
  wider.crest_factor = 2.0;
  EXPECT_NEAR(wider.normal_force(stress, tangent), expected, 1e-9 * expected);
}

TEST(HighModeWaves, RejectsBadParameters) {
  const auto rejects = [](auto&& change, const std::string& field) {
    HighModeWaves waves = plate_waves();
    change(waves);
    try {
      waves.validate();
      ADD_FAILURE() << field << " accepted";
    } catch (const brb::ParameterError& error) {
      EXPECT_EQ(error.field(), field) << error.what();
    }
  };
  rejects([](HighModeWaves& w) { w.area = 0.0; }, "area");
  rejects([](HighModeWaves& w) { w.gyration_radius = -1.0; }, "gyration_radius");
  rejects([](HighModeWaves& w) { w.thickness = 0.0; }, "thickness");
  rejects([](HighModeWaves& w) { w.gap = -0.1; }, "gap");
  rejects([](HighModeWaves& w) { w.tributary_length = 0.0; }, "tributary_length");
  rejects([](HighModeWaves& w) { w.resolved_half_wave = NAN; }, "resolved_half_wave");
  rejects([](HighModeWaves& w) { w.crest_factor = -4.0; }, "crest_factor");
  EXPECT_NO_THROW(plate_waves().validate());
}

/// Gaps of 1 mm, so the straight core of the probe never bears: only the waves press on the
/// casing.
CasingContactParameters wave_link() {
  CasingContactParameters p;
  p.gap_y = 1.0;
  p.gap_z = 1.0;
  p.bearing_area_y = 1000.0;
  p.bearing_area_z = 6000.0;
  p.bearing_depth_y = 20.0;
  p.bearing_depth_z = 20.0;
  p.mortar = {27600.0, 0.2, 34.5, 3.45, 0.1};
  p.layer_stiffness = 5.0;
  p.friction_coefficient = 0.1;
  p.tangential_stiffness = 1e6;
  return p;
}

/// The interior-station probe around the 60 x 10 mm plate, the core keeping its size
/// (nu_c = 0: the chord only), with plate_waves().
test::ExpansionProbe wave_probe() {
  return test::ExpansionProbe(wave_link(), 60.0, 10.0, true, 0.0, plate_waves());
}

TEST(HighModeWaves, LinkSlidesAtKappaTimesTheWavesNormalForceFromTheStepBefore) {
  // Reference: Coulomb friction (|T| = kappa N while sliding) on N_w from the core's stress
  // and tangent at the start of the step, those of the uniaxial steel law at the chord's
  // strain; the gaps stay open, so N_w is the whole normal force and there is no lateral
  // force.
  test::ExpansionProbe probe = wave_probe();
  const HighModeWaves waves = plate_waves();
  const material::SteelUniaxial steel(waves.steel, 2.0 * test::ExpansionProbe::half_chord);
  material::SteelStateUniaxial state;
  double previous_stress = 0.0, previous_tangent = waves.steel.youngs_modulus;
  int sliding_steps = 0;
  for (int step = 1; step <= 20; ++step) {
    const double strain = -0.001 * step; // to 2 %, about 16 times the yield strain
    const double slip = 0.05 * step;     // the core moves along the casing: sliding
    probe.place(Vector3(slip, 0.0, 0.0), strain);
    probe.evaluate();
    const double expected_normal = waves.normal_force(previous_stress, previous_tangent);
    EXPECT_NEAR(probe.contact.wave_normal_force(), expected_normal, 1e-9 * (expected_normal + 1.0))
        << "step " << step;
    EXPECT_EQ(probe.contact.normal_force(), 0.0); // no face bears
    if (expected_normal > 0.0) {
      // sliding in +x: the resisting (internal) force on the core is +kappa N_w, on the
      // casing its opposite
      EXPECT_NEAR(probe.contact.link_force()[0], 0.1 * expected_normal, 1e-9 * expected_normal)
          << "step " << step;
      EXPECT_NEAR(probe.force[0], 0.1 * expected_normal, 1e-9 * expected_normal);
      EXPECT_NEAR(probe.force[6], -0.1 * expected_normal, 1e-9 * expected_normal);
      ++sliding_steps;
    }
    EXPECT_NEAR(probe.force.segment<2>(1).norm(), 0.0, 1e-12);
    probe.contact.commit();
    const auto response = steel.evaluate(state, strain);
    state = response.state;
    previous_stress = response.stress;
    previous_tangent = response.tangent;
  }
  EXPECT_GT(sliding_steps, 10); // the plastic range was reached and slid through
  // Reversed into tension: the stress becomes tensile, the step after it has no waves.
  probe.place(Vector3(1.0, 0.0, 0.0), 0.01);
  probe.evaluate();
  probe.contact.commit();
  probe.place(Vector3(1.1, 0.0, 0.0), 0.011);
  probe.evaluate();
  EXPECT_EQ(probe.contact.wave_normal_force(), 0.0);
  EXPECT_NEAR(probe.contact.link_force()[0], 0.0, 1e-9);
}

TEST(HighModeWaves, TangentMatchesFiniteDifferencesWhileTheWavesHoldTheCore) {
  // Reference: central differences of the nodal forces; N_w is fixed within the step, so the
  // tangent is that of friction at a given normal force, in stick (a small slip after a
  // committed state) and while sliding.
  test::ExpansionProbe probe = wave_probe();
  probe.place(Vector3(0.0, 0.0, 0.0), -0.01);
  probe.evaluate();
  probe.contact.commit();
  probe.place(Vector3(0.0, 0.0, 0.0), -0.015);
  probe.evaluate();
  probe.contact.commit();
  ASSERT_GT(probe.contact.wave_normal_force(), 0.0);
  for (const double slip : {1e-7, 0.5}) { // stick, then sliding
    probe.place(Vector3(slip, 0.0, 0.0), -0.0151);
    probe.evaluate();
    const Eigen::MatrixXd analytic = probe.tangent;
    const Eigen::MatrixXd numeric = test::numeric_element_tangent(probe.contact, probe.nodes, 1e-9);
    EXPECT_LT(test::relative_difference(analytic, numeric), 1e-6) << "slip " << slip;
  }
}

TEST(HighModeWaves, NeedTheCoreChord) {
  const CasingContactParameters parameters = wave_link();
  EXPECT_THROW(CasingContact({0, 1}, Vector3::Zero(), Vector3::Zero(), parameters, true,
                             std::nullopt, plate_waves()),
               brb::ParameterError);
}

} // namespace
} // namespace brb::element
