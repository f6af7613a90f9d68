// Truss (CorotTruss with a UniaxialLaw chosen at construction, built by make_truss): elastic
// axial stiffness, the steel law along a cyclic history, and the energy it reports.
#include "brb/element/frame_element_specs.hpp"
#include "brb/element/truss.hpp"
#include "brb/material/parameter_error.hpp"

#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace brb::element {
namespace {

const Vector3 kStart(120.0, -40.0, 15.0);
const Vector3 kAxis = Vector3(2.0, -1.0, 1.5).normalized(); // skew: in no coordinate plane
constexpr double kLength = 2500.0, kArea = 800.0;

/// Forces and tangent of the truss with node j moved to give the strain eps along the axis.
struct Stretched {
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
};

Stretched stretch(Truss& truss, double strain) {
  const std::vector<NodeConfiguration> nodes{
      {kStart, Matrix3::Identity()},
      {kStart + (1.0 + strain) * kLength * kAxis, Matrix3::Identity()}};
  Stretched result;
  std::string failure;
  EXPECT_TRUE(truss.evaluate(nodes, result.force, result.tangent, failure)) << failure;
  return result;
}

std::unique_ptr<Truss> make(const UniaxialLawParameters& material) {
  return make_truss({{0, 1}, kArea, material}, kStart, kStart + kLength * kAxis);
}

/// A cyclic strain history with growing amplitudes (0.2 %, 1 %, 2.5 %) in steps of 1e-5.
std::vector<double> cyclic_history() {
  std::vector<double> history{0.0};
  const double step = 1e-5;
  for (const double amplitude : {0.002, 0.01, 0.025}) {
    for (const double target : {amplitude, -amplitude}) {
      while (std::abs(history.back() - target) > 0.5 * step)
        history.push_back(history.back() + (target > history.back() ? step : -step));
    }
  }
  while (std::abs(history.back()) > 0.5 * step)
    history.push_back(history.back() + (history.back() < 0.0 ? step : -step));
  return history;
}

TEST(Truss, ElasticAxialStiffnessAlongASkewAxis) {
  // Reference: a bar of modulus E, area A and length L: axial stiffness E A / L along its
  // axis, no transverse stiffness while unloaded, N = E A Delta / L.
  const double youngs = 200000.0;
  const auto truss = make(ElasticLawParameters{youngs});
  const Stretched rest = stretch(*truss, 0.0);
  const Eigen::Matrix3d block = rest.tangent.block<3, 3>(6, 6);
  const double axial = youngs * kArea / kLength;
  EXPECT_NEAR(kAxis.dot(block * kAxis), axial, 1e-12 * axial);
  const Vector3 normal = kAxis.cross(Vector3::UnitZ()).normalized();
  EXPECT_LT((block * normal).norm(), 1e-12 * axial);
  EXPECT_LT(rest.force.norm(), 1e-9);

  const Stretched pulled = stretch(*truss, 1e-3);
  EXPECT_NEAR(pulled.force.segment<3>(6).dot(kAxis), axial * 1e-3 * kLength, 1e-9 * axial);
  // stored energy E A Delta^2 / (2 L)
  EXPECT_NEAR(truss->energy().stored, 0.5 * axial * std::pow(1e-3 * kLength, 2),
              1e-9 * axial * std::pow(1e-3 * kLength, 2));
}

TEST(Truss, SteelLawForceFollowsTheUniaxialLawAlongACyclicHistory) {
  // Reference: the truss is one material point: N = A sigma(eps) of SteelUniaxial (lc = L)
  // driven on its own along the same strain history (independent evaluation of the law).
  const material::SteelParameters steel = test::chaboche_voce_steel();
  const auto truss = make(steel);
  const material::SteelUniaxial law(steel, kLength);
  material::SteelStateUniaxial state = law.initial_state();
  double worst = 0.0;
  for (const double strain : cyclic_history()) {
    const double force = stretch(*truss, strain).force.segment<3>(6).dot(kAxis);
    truss->commit();
    const auto response = law.evaluate(state, strain);
    state = response.state;
    worst = std::max(worst, std::abs(force - kArea * response.stress));
  }
  EXPECT_LT(worst, 1e-12 * kArea * steel.yield_stress);
}

TEST(Truss, EnergyEqualsTheWorkOfTheAxialForce) {
  // Reference: stored + dissipated = integral of N d(elongation), here by the trapezoidal rule
  // on the path of steps 1e-5 (strain). Its error is O(h^2) on smooth parts plus at most
  // E A h^2 / 8 per yield kink (h the elongation step): 1e-5 of the total work bounds both.
  const material::SteelParameters steel = test::chaboche_voce_steel();
  const auto truss = make(steel);
  double work = 0.0, previous_force = 0.0, previous_elongation = 0.0;
  for (const double strain : cyclic_history()) {
    const double force = stretch(*truss, strain).force.segment<3>(6).dot(kAxis);
    truss->commit();
    const double elongation = truss->strain() * kLength;
    work += 0.5 * (force + previous_force) * (elongation - previous_elongation);
    previous_force = force;
    previous_elongation = elongation;
  }
  const ElementEnergy energy = truss->energy();
  EXPECT_GT(energy.dissipated, 0.0);
  EXPECT_NEAR(energy.stored + energy.dissipated, work, 1e-5 * work);
}

TEST(Truss, MortarLawFollowsTheUniaxialLawThroughTheVariant) {
  // Reference: MortarUniaxial (lc = L) driven on its own: tension past ft (cracking and
  // softening), then compression; N = A sigma to round-off.
  material::MortarParameters mortar;
  mortar.youngs_modulus = 30000.0;
  mortar.compressive_strength = 40.0;
  mortar.tensile_strength = 3.0;
  mortar.fracture_energy = 5.0; // long enough a softening branch for L = 2500 mm
  const auto truss = make(mortar);
  const material::MortarUniaxial law(mortar, kLength);
  material::MortarState state = law.initial_state();
  double worst = 0.0, peak = 0.0;
  for (int step = 0; step <= 400; ++step) {
    const double strain = step <= 200 ? 1e-6 * step : 2e-4 - 3e-6 * (step - 200);
    const double force = stretch(*truss, strain).force.segment<3>(6).dot(kAxis);
    truss->commit();
    const auto response = law.evaluate(state, strain);
    state = response.state;
    worst = std::max(worst, std::abs(force - kArea * response.stress));
    peak = std::max(peak, force);
  }
  EXPECT_LT(worst, 1e-12 * kArea * mortar.compressive_strength);
  EXPECT_GT(truss->energy().dissipated, 0.0); // it cracked
  EXPECT_LE(peak, kArea * mortar.tensile_strength * (1.0 + 1e-12));
}

TEST(Truss, MakeTrussRejectsBadParametersNamingTheField) {
  const auto field_of = [](const TrussSpec& spec, const Vector3& end) -> std::string {
    try {
      make_truss(spec, kStart, end);
    } catch (const ParameterError& error) {
      return error.field();
    }
    return "";
  };
  const Vector3 end = kStart + kLength * kAxis;
  EXPECT_EQ(field_of({{0, 1}, 0.0, ElasticLawParameters{200000.0}}, end), "area");
  EXPECT_EQ(field_of({{0, 1}, kArea, ElasticLawParameters{0.0}}, end), "E");
  EXPECT_EQ(field_of({{0, 1}, kArea, ElasticLawParameters{200000.0}}, kStart), "nodes");
  material::SteelParameters steel = test::linear_mixed_steel();
  steel.yield_stress = -1.0;
  EXPECT_EQ(field_of({{0, 1}, kArea, steel}, end), "fy");
  EXPECT_EQ(field_of({{0, 1}, kArea, ElasticLawParameters{200000.0}}, end), "");
}

} // namespace
} // namespace brb::element
