// The `truss` fidelity of the BRB element (BraceTruss): the series stiffness of the yielding
// core and the elastic end zones, the yield force fy A, and a cyclic test against the
// closed-form uniaxial steel law evaluated on the element's own core-strain history.
#include "brb/analysis/static_analysis.hpp"
#include "brb/element/brace_truss.hpp"
#include "brb/element/rotation.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_model.hpp"

#include "support/brace_fixtures.hpp"
#include "support/finite_difference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace brb::element {
namespace {

/// Area of a fiber layout of a circle of diameter d, as the element gets it.
double mesh_area(const model::SectionSpec& section) {
  return section.mesh().total_area();
}

TEST(BraceTruss, ElasticStiffnessIsTheSeriesFormulaOfTheZones) {
  // Reference: 1 / sum L_i / (E A_i) over the yielding core and both ends' transition and
  // connection zones (springs in series), written out from the Girona D3 geometry.
  const model::BraceSpec spec = test::girona_d3_bare_core(16, true);
  const double E = spec.steel.youngs_modulus;
  const double flexibility = spec.yielding_length / (E * mesh_area(spec.core_section)) +
                             2.0 * 36.0 / (E * mesh_area(spec.transition->section)) +
                             2.0 * 270.0 / (E * mesh_area(spec.connection->section));
  const BraceTrussParameters parameters = model::truss_parameters(spec);
  // an arbitrary direction: the stiffness along the chord does not depend on it
  const Vector3 axis = Vector3(0.2, -0.5, 0.84).normalized();
  const Vector3 start(10.0, 20.0, -5.0);
  const Vector3 end = start + spec.total_length() * axis;
  BraceTruss truss({0, 1}, start, end, parameters);
  EXPECT_NEAR(truss.elastic_stiffness(), 1.0 / flexibility, 1e-12 / flexibility);

  std::array<NodeConfiguration, 2> nodes;
  nodes[0].position = start;
  const double deformation = 0.5; // mm, elastic (dy is about 2.9 mm)
  nodes[1].position = end + deformation * axis;
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(truss.evaluate(nodes, force, tangent, failure)) << failure;
  EXPECT_NEAR(truss.axial_force(), deformation / flexibility, 1e-9 * deformation / flexibility);
  EXPECT_NEAR(axis.dot(tangent.block<3, 3>(6, 6) * axis), 1.0 / flexibility, 1e-9 / flexibility);
  // end zones elastic: the core takes Delta - N f_e
  const double end_zones = flexibility - spec.yielding_length / (E * mesh_area(spec.core_section));
  EXPECT_NEAR(truss.core_strain() * spec.yielding_length,
              deformation - truss.axial_force() * end_zones, 1e-12);
}

TEST(BraceTruss, YieldsAtFyTimesTheCoreArea) {
  // Without hardening the force stays at fy A once the core yields, however far it goes.
  model::BraceSpec spec = test::girona_d3_bare_core(16, true);
  spec.steel.kinematic_hardening = 0.0;
  spec.steel.isotropic_hardening = 0.0;
  model::BraceModel brace = model::build_brace_truss_model(spec);
  const double py = spec.steel.yield_stress * mesh_area(spec.core_section);
  EXPECT_DOUBLE_EQ(brace.yield_force, py);
  analysis::StaticAnalysis analysis(brace.model);
  analysis.use_displacement_control(brace.end_node, model::ux);
  ASSERT_TRUE(analysis.step_to(0.999 * brace.yield_deformation).converged);
  EXPECT_LT(analysis.control_force(), py);
  EXPECT_NEAR(analysis.control_force(), 0.999 * py, 1e-9 * py);
  for (const double multiple : {1.5, 5.0, -5.0}) {
    ASSERT_TRUE(analysis.step_to(multiple * brace.yield_deformation).converged);
    EXPECT_NEAR(std::abs(analysis.control_force()), py, 1e-9 * py) << multiple;
  }
}

TEST(BraceTruss, CyclicTestFollowsTheUniaxialSteelLawOnItsCoreStrain) {
  // Reference: SteelUniaxial driven independently through the element's core-strain history
  // (backward Euler from step to step, as `brb material` does); the element's force must be
  // A sigma and its deformation eps L_y + N f_e at every step, and the dissipation must match.
  const model::BraceSpec spec = test::girona_d3_bare_core(16, true);
  model::BraceModel brace = model::build_brace_truss_model(spec);
  const BraceTrussParameters parameters = model::truss_parameters(spec);
  const double dy = brace.yield_deformation;
  const io::LoadingProtocol protocol =
      io::cyclic_protocol("truss", {{0.5 * dy, 1}, {2.0 * dy, 2}, {5.0 * dy, 1}}, dy / 10.0);
  analysis::StaticAnalysis analysis(brace.model);
  analysis.use_displacement_control(brace.end_node, model::ux);
  const material::SteelUniaxial law(spec.steel, spec.yielding_length);
  material::SteelStateUniaxial state = law.initial_state();
  double largest_force_error = 0.0, largest_split_error = 0.0;
  for (std::size_t k = 1; k < protocol.deformation.size(); ++k) {
    ASSERT_TRUE(analysis.step_to(protocol.deformation[k]).converged) << k;
    const double strain = brace.truss->core_strain();
    const auto response = law.evaluate(state, strain);
    state = response.state;
    const double force = parameters.core_area * response.stress;
    largest_force_error = std::max(largest_force_error, std::abs(analysis.control_force() - force));
    largest_split_error =
        std::max(largest_split_error,
                 std::abs(strain * parameters.yielding_length + force * parameters.end_flexibility -
                          protocol.deformation[k]));
  }
  EXPECT_LT(largest_force_error, 1e-9 * brace.yield_force);
  EXPECT_LT(largest_split_error, 1e-9 * dy);
  const double volume = parameters.core_area * parameters.yielding_length;
  EXPECT_NEAR(analysis.energy().dissipated,
              volume * material::SteelUniaxial::dissipated_energy(state),
              1e-9 * analysis.energy().dissipated);
  EXPECT_GT(analysis.energy().dissipated, 10.0 * brace.yield_force * dy); // it did yield
  EXPECT_LT(analysis.energy().law_relative_error(), 1e-2);
  // The truss's kinematics are linear along its axis: with the laws' integration misfit (the
  // core's trapezoidal work on its elongation; the end zones are linear) set apart, the
  // balance holds to the equilibrium tolerance.
  EXPECT_LT(analysis.energy().relative_error(), 1e-9);
}

TEST(BraceTruss, TangentMatchesCentralDifferencesInAnyDirection) {
  // Reference: central differences of the nodal forces, on the plastic branch (from a
  // committed yielded state, loading further) and with a rotated chord (geometric term).
  const model::BraceSpec spec = test::girona_d3_bare_core(16, true);
  const BraceTrussParameters parameters = model::truss_parameters(spec);
  const Vector3 axis = Vector3(0.6, 0.0, 0.8);
  const Vector3 start = Vector3::Zero(), end = spec.total_length() * axis;
  BraceTruss truss({0, 1}, start, end, parameters);
  std::array<NodeConfiguration, 2> nodes;
  nodes[0].position = start;
  nodes[1].position = end + 6.0 * axis; // about 2 dy
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  ASSERT_TRUE(truss.evaluate(nodes, force, tangent, failure));
  truss.commit();
  Eigen::VectorXd x(6);
  x << 0.1, -0.2, 0.05, 1.0 + 0.6 * 3.0, 2.5, 0.8 * 3.0; // further tension, turned chord
  const auto forces = [&](const Eigen::VectorXd& u) {
    std::array<NodeConfiguration, 2> trial = nodes;
    trial[0].position += u.head<3>();
    trial[1].position += u.tail<3>();
    Eigen::VectorXd f;
    Eigen::MatrixXd k;
    std::string why;
    EXPECT_TRUE(truss.evaluate(trial, f, k, why));
    Eigen::VectorXd translational(6);
    translational << f.segment<3>(0), f.segment<3>(6);
    return translational;
  };
  const Eigen::MatrixXd numerical = test::central_difference_jacobian(forces, x, 1e-6);
  forces(x);
  ASSERT_TRUE(truss.evaluate(
      std::array<NodeConfiguration, 2>{NodeConfiguration{nodes[0].position + x.head<3>()},
                                       NodeConfiguration{nodes[1].position + x.tail<3>()}},
      force, tangent, failure));
  Eigen::MatrixXd analytic(6, 6);
  analytic << tangent.block<3, 3>(0, 0), tangent.block<3, 3>(0, 6), tangent.block<3, 3>(6, 0),
      tangent.block<3, 3>(6, 6);
  EXPECT_LT(test::relative_difference(analytic, numerical), 1e-6);
}

} // namespace
} // namespace brb::element
