// CorotBeam3D at element level: rigid-body motion and the consistent tangent.
#include "brb/element/corot_beam_3d.hpp"
#include "brb/element/rotation.hpp"
#include "brb/material/mortar_damage.hpp"
#include "brb/material/steel_uniaxial.hpp"
#include "brb/section/elastic_section.hpp"

#include "support/finite_difference.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

namespace brb::element {
namespace {

using FiberBeam = CorotBeam3D<section::FiberSection<material::SteelUniaxial>>;

section::ElasticSectionProperties steel_bar() {
  // 30 x 10 mm steel bar: E A, E I_y, E I_z, G J
  return {210000.0 * 300.0, 210000.0 * 2500.0, 210000.0 * 22500.0, 80769.0 * 2.63 * 3000.0};
}

std::vector<NodeConfiguration> moved(std::vector<NodeConfiguration> nodes,
                                     const Eigen::VectorXd& increment) {
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    nodes[n].position += increment.segment<3>(6 * n);
    nodes[n].rotation = rotation_from_vector(increment.segment<3>(6 * n + 3)) * nodes[n].rotation;
  }
  return nodes;
}

TEST(CorotBeam3D, RigidBodyRotationProducesNoStrainAndNoForce) {
  // Reference: rigid-body motion does no work, so a beam must show zero local deformation
  // and zero force after 90-degree rotations about each axis and a combined 3D rotation.
  const Vector3 start(0.0, 0.0, 0.0), end(500.0, 0.0, 0.0);
  const auto integration = BeamIntegration::make(IntegrationRule::gauss_lobatto, 3);
  CorotBeam3D<section::ElasticSection> beam({0, 1}, start, end, Vector3(0, 0, 1), integration,
                                            std::vector(3, section::ElasticSection(steel_bar())));
  const double quarter = std::numbers::pi / 2.0;
  for (const Vector3& axis : {Vector3(quarter, 0, 0), Vector3(0, quarter, 0),
                              Vector3(0, 0, quarter), Vector3(0.9, -1.3, 0.4)}) {
    const Matrix3 q = rotation_from_vector(axis);
    std::vector<NodeConfiguration> nodes{{q * start + Vector3(5, 6, 7), q},
                                         {q * end + Vector3(5, 6, 7), q}};
    Eigen::VectorXd force;
    Eigen::MatrixXd tangent;
    std::string failure;
    ASSERT_TRUE(beam.evaluate(nodes, force, tangent, failure)) << failure;
    EXPECT_LT(beam.frame().local_deformation().norm(), 1e-10 * 500.0);
    EXPECT_LT(force.norm(), 1e-10 * steel_bar().axial_stiffness);
  }
}

TEST(CorotBeam3D, InelasticTangentMatchesFiniteDifferences) {
  // Reference: central differences of the element force from the same committed state,
  // at a deformed, yielded configuration (fiber section, closed-form steel law).
  const Vector3 start(0.0, 0.0, 0.0), end(400.0, 30.0, -20.0);
  const auto integration = BeamIntegration::make(IntegrationRule::gauss_lobatto, 4);
  const auto steel = test::chaboche_voce_steel();
  std::vector<section::FiberSection<material::SteelUniaxial>> sections;
  for (std::size_t k = 0; k < integration.weights.size(); ++k) {
    sections.emplace_back(section::mesh_rectangle(30.0, 10.0, 4, 8),
                          material::SteelUniaxial(steel, integration.weights[k] * 400.0), 80769.0);
  }
  FiberBeam beam({0, 1}, start, end, Vector3(0, 0, 1), integration, std::move(sections));
  const std::vector<NodeConfiguration> initial{{start, Matrix3::Identity()},
                                               {end, Matrix3::Identity()}};
  Eigen::VectorXd load_path(12);
  load_path << 0, 0, 0, 0.01, -0.02, 0.015, 0.9, 1.5, -2.0, -0.02, 0.05, 0.03;
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
  std::string failure;
  // load in increments, committing (plastic history), then check at a new trial state
  for (int step = 1; step <= 5; ++step) {
    ASSERT_TRUE(beam.evaluate(moved(initial, 0.2 * step * load_path), force, tangent, failure))
        << failure;
    beam.commit();
  }
  const auto current = moved(initial, 1.1 * load_path);
  ASSERT_TRUE(beam.evaluate(current, force, tangent, failure)) << failure;
  const auto force_of = [&](const Eigen::VectorXd& increment) {
    Eigen::VectorXd f;
    Eigen::MatrixXd unused;
    std::string why;
    EXPECT_TRUE(beam.evaluate(moved(current, increment), f, unused, why));
    return f;
  };
  const Eigen::MatrixXd numeric =
      test::central_difference_jacobian(force_of, Eigen::VectorXd::Zero(12).eval(), 1e-7);
  EXPECT_LT(test::relative_difference(tangent, numeric), 1e-6);
  // the yielded state: some fiber is plastic
  double plastic = 0.0;
  for (const auto& section : beam.local_beam().sections()) {
    for (const auto& state : section.committed_states()) {
      plastic = std::max(plastic, state.equivalent_plastic_strain);
    }
  }
  EXPECT_GT(plastic, 0.0);
}

using FiberLocalBeam = LocalBeam<section::FiberSection<material::SteelUniaxial>>;

/// The equal-force solve's tolerance at the beam's last evaluation: 1e-10 of the largest
/// point force plus the force of a 1e-6 strain (LocalBeam::axial_tolerance).
double axial_force_tolerance(const FiberLocalBeam& beam) {
  double force_scale = 0.0, stiffness_scale = 0.0;
  for (const auto& section : beam.sections()) {
    force_scale = std::max(force_scale, std::abs(section.last_response().force[0]));
    stiffness_scale = std::max(stiffness_scale, std::abs(section.last_response().tangent(0, 0)));
  }
  return 1e-10 * (force_scale + 1e-6 * stiffness_scale);
}

/// Evaluates `beam` at 400 random trial deformations around `deformation` (axial change up to
/// +-axial_range mm, end rotations up to +-rotation_range) and checks each against
/// equilibrium itself: one axial force at every point (to the element's tolerance, 1e-10 of
/// the force plus the force of a 1e-6 strain) and compatibility sum_k w_k e0_k = u / L0.
void expect_trials_in_axial_equilibrium(FiberLocalBeam& beam, const LocalVector& deformation,
                                        double axial_range, double rotation_range, unsigned seed) {
  const BeamIntegration& integration = beam.integration();
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  LocalVector force;
  LocalMatrix tangent;
  std::string failure;
  for (int trial = 0; trial < 400; ++trial) {
    LocalVector trial_deformation = deformation;
    trial_deformation[0] += axial_range * unit(generator);
    for (const int bend : {2, 3, 5, 6})
      trial_deformation[bend] += rotation_range * unit(generator);
    ASSERT_TRUE(beam.evaluate(trial_deformation, force, tangent, failure))
        << "trial " << trial << ": " << failure;
    double mean_strain = 0.0;
    for (std::size_t k = 0; k < integration.weights.size(); ++k)
      mean_strain += integration.weights[k] * beam.axial_strains()[k];
    EXPECT_NEAR(mean_strain, trial_deformation[0] / beam.length(), 1e-12);
    for (std::size_t k = 0; k < integration.weights.size(); ++k) {
      EXPECT_NEAR(beam.sections()[k].last_response().force[0], force[0],
                  axial_force_tolerance(beam))
          << "trial " << trial << ", point " << k;
    }
  }
}

/// A plate core of UCSD G1 (BRB_SOURCE_FACTS section 8: 203.2 x 38.1 mm, linear kinematic
/// hardening H = 3.3 % of E), 210 mm long on 3 Gauss-Lobatto points, driven to tension at 2
/// dy and back to compression at 1.6 dy with a growing bending wave (theta about z of the
/// 38.1 mm depth: opposite end rotations, the curvature of a buckling half-wave), each stage
/// committed. `deformation` returns the last stage's.
constexpr double kG1YieldStrain = 255.106 / 199948.0; ///< fy / E of G1's plate

FiberLocalBeam yielded_g1_plate(LocalVector& deformation) {
  material::SteelParameters steel;
  steel.youngs_modulus = 199948.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 255.106;
  steel.kinematic_hardening = 6598.3;
  const double length = 210.0;
  const auto integration = BeamIntegration::make(IntegrationRule::gauss_lobatto, 3);
  std::vector<section::FiberSection<material::SteelUniaxial>> sections;
  for (std::size_t k = 0; k < integration.weights.size(); ++k) {
    sections.emplace_back(section::mesh_rectangle(203.2, 38.1, 8, 4),
                          material::SteelUniaxial(steel, integration.weights[k] * length), 76903.0);
  }
  FiberLocalBeam beam(length, integration, std::move(sections));
  deformation = LocalVector::Zero();
  LocalVector force;
  LocalMatrix tangent;
  std::string failure;
  for (const auto& [strain, rotation] : {std::pair{2.0, 0.0}, std::pair{0.5, 0.004},
                                         std::pair{-1.0, 0.008}, std::pair{-1.6, 0.012}}) {
    deformation[0] = strain * kG1YieldStrain * length;
    deformation[3] = rotation;
    deformation[6] = -0.6 * rotation;
    EXPECT_TRUE(beam.evaluate(deformation, force, tangent, failure)) << failure;
    beam.commit();
  }
  return beam;
}

TEST(LocalBeam, AxialEquilibriumIsFoundWherePlainNewtonCyclesBetweenBranches) {
  // G1's plate core, yielded in compression with weak-axis curvature, then driven to random
  // trial deformations near its state. Its points cross between elastic and plastic
  // branches at different strains, where Newton's method on the point strains can cycle
  // (measured on G1: a period-4 cycle). Reference: equilibrium itself; every trial must
  // give one axial force at every point (to the element's tolerance, 1e-10 of the force
  // plus the force of a 1e-6 strain) and satisfy compatibility sum_k w_k e0_k = u / L0.
  // The trials follow each other without a revert, so each starts from the previous one's
  // strains moved by its tangent (the predictor), from up to 2 dy and 0.02 rad away.
  LocalVector deformation;
  FiberLocalBeam beam = yielded_g1_plate(deformation);
  expect_trials_in_axial_equilibrium(beam, deformation, 2.0 * kG1YieldStrain * beam.length(), 0.02,
                                     20261123);
}

TEST(LocalBeam, ThePredictedStartFindsTheColdStartsEquilibriumInFewerSweeps) {
  // The iterates of a global Newton solve approach the step's end: here a further 0.5 dy of
  // shortening and a deeper bending wave on G1's yielded plate, as d_i = d_c + (1 - 2^-i) D,
  // i = 1..8. One beam starts each equal-force solve from the committed strains, the other
  // from the last trial's moved by its tangent. Reference: the cold start's solution; the
  // equilibrium is unique for this hardening plate, and both solves stop within the
  // solve's tolerance of it (1e-10 of the force plus the force of a 1e-6 strain), so their
  // axial forces differ by at most twice that; the end moments (the points' curvatures are
  // the same, their axial strains differ by that force over the axial stiffness) to 1e-8 of
  // their size (measured well below).
  LocalVector committed;
  FiberLocalBeam predicted = yielded_g1_plate(committed);
  FiberLocalBeam cold = yielded_g1_plate(committed);
  EXPECT_TRUE(predicted.axial_predictor()); // steel without damage: hardening fibers
  cold.set_axial_predictor(false);
  LocalVector step = LocalVector::Zero();
  step[0] = -0.5 * kG1YieldStrain * predicted.length();
  step[3] = 0.002;
  step[6] = -0.0012;
  LocalVector force_predicted, force_cold;
  LocalMatrix tangent_predicted, tangent_cold;
  std::string failure;
  int sweeps_predicted = 0, sweeps_cold = 0;
  for (int iterate = 1; iterate <= 8; ++iterate) {
    const LocalVector trial = committed + (1.0 - std::ldexp(1.0, -iterate)) * step;
    ASSERT_TRUE(predicted.evaluate(trial, force_predicted, tangent_predicted, failure)) << failure;
    ASSERT_TRUE(cold.evaluate(trial, force_cold, tangent_cold, failure)) << failure;
    EXPECT_NEAR(force_predicted[0], force_cold[0], 2.0 * axial_force_tolerance(cold))
        << "iterate " << iterate;
    const double moment_scale = force_cold.tail<6>().cwiseAbs().maxCoeff();
    EXPECT_LT((force_predicted - force_cold).tail<6>().cwiseAbs().maxCoeff(), 1e-8 * moment_scale)
        << "iterate " << iterate;
    sweeps_predicted += predicted.axial_sweeps();
    sweeps_cold += cold.axial_sweeps();
    std::cout << "[ predictor ] iterate " << iterate << ": sweeps " << predicted.axial_sweeps()
              << " (cold " << cold.axial_sweeps() << "), N " << force_predicted[0] << " vs "
              << force_cold[0] << "\n";
    if (iterate >= 4) { // the iterates' change is a sixteenth of the step or less
      EXPECT_EQ(predicted.axial_sweeps(), 1) << "iterate " << iterate;
    }
  }
  EXPECT_LT(sweeps_predicted, sweeps_cold);

  // A revert forgets the last trial: both start from the committed strains, the same solve
  predicted.revert_to_committed();
  cold.revert_to_committed();
  ASSERT_TRUE(predicted.evaluate(committed + step, force_predicted, tangent_predicted, failure));
  ASSERT_TRUE(cold.evaluate(committed + step, force_cold, tangent_cold, failure));
  EXPECT_EQ(predicted.axial_sweeps(), cold.axial_sweeps());
  EXPECT_TRUE(force_predicted == force_cold); // bitwise: the same arithmetic
}

TEST(LocalBeam, AxialEquilibriumIsFoundWhereNewtonThrowsASaturatedPointFar) {
  // CB225's calibrated steel (validation/CALIBRATION.md): two Chaboche back-stresses and a
  // negligible Voce term, so the stress saturates at fy + C1 / gamma1 + C2 / gamma2 = 383 MPa
  // and a point far into a compression excursion keeps an axial stiffness of a few hundred
  // MPa times its area. Bent as in a buckled core, a trial deformation that asks one point
  // for a force change its stiffness can only give through a strain far outside its branch
  // threw Newton's iterate out of the law's domain, and the element failed ("singular or
  // non-finite axial section stiffness"; measured: CB225 with the sub-element waves stopped
  // at 1.75 % shortening). Reference: equilibrium itself, as in the test above.
  material::SteelParameters steel;
  steel.youngs_modulus = 199948.0;
  steel.poissons_ratio = 0.3;
  steel.yield_stress = 186.296;
  steel.chaboche = {{111760.6, 974.224}, {6294.2, 76.456}};
  steel.voce_saturation = 0.1;
  steel.voce_rate = 100.0;
  const double length = 370.0;
  const auto integration = BeamIntegration::make(IntegrationRule::gauss_lobatto, 3);
  std::vector<section::FiberSection<material::SteelUniaxial>> sections;
  for (std::size_t k = 0; k < integration.weights.size(); ++k) {
    sections.emplace_back(section::mesh_rectangle(93.33, 15.55, 6, 4),
                          material::SteelUniaxial(steel, integration.weights[k] * length), 76903.0);
  }
  FiberLocalBeam beam(length, integration, std::move(sections));
  LocalVector deformation = LocalVector::Zero();
  LocalVector force;
  LocalMatrix tangent;
  std::string failure;
  // 3.4 % elongation, then 1.75 % shortening with the end rotations of a buckling wave, in
  // steps of 0.05 % strain
  const std::array<std::pair<double, double>, 3> targets{
      {{0.034, 0.0}, {0.0, 0.01}, {-0.0175, 0.02}}};
  double strain = 0.0, rotation = 0.0;
  for (const auto& [target_strain, target_rotation] : targets) {
    const int steps = static_cast<int>(std::ceil(std::abs(target_strain - strain) / 5e-4));
    const double strain_step = (target_strain - strain) / steps;
    const double rotation_step = (target_rotation - rotation) / steps;
    for (int step = 0; step < steps; ++step) {
      strain += strain_step;
      rotation += rotation_step;
      deformation[0] = strain * length;
      deformation[3] = rotation;
      deformation[6] = -rotation;
      ASSERT_TRUE(beam.evaluate(deformation, force, tangent, failure)) << failure;
      beam.commit();
    }
  }
  expect_trials_in_axial_equilibrium(beam, deformation, 0.002 * length, 0.03, 20261124);
}

using MortarLocalBeam = LocalBeam<section::FiberSection<material::MortarUniaxial>>;

/// The mortar casing of the source's small BRB (BRB_SOURCE_FACTS section 6: 30 x 30 mm, E
/// 17520, nu 0.2, fc 39.92, ft 3.992 MPa, Gf 0.75 N/mm) as a 50 mm local beam with three
/// Gauss-Lobatto sections.
MortarLocalBeam small_brb_mortar_beam() {
  const material::MortarParameters mortar{17520.0, 0.2, 39.92, 3.992, 0.75};
  const double length = 50.0;
  const auto integration = BeamIntegration::make(IntegrationRule::gauss_lobatto, 3);
  std::vector<section::FiberSection<material::MortarUniaxial>> sections;
  for (std::size_t k = 0; k < integration.weights.size(); ++k) {
    sections.emplace_back(section::mesh_rectangle(30.0, 30.0, 6, 6),
                          material::MortarUniaxial(mortar, integration.weights[k] * length),
                          7300.0);
  }
  return MortarLocalBeam(length, integration, std::move(sections));
}

/// The mortar beam's deformation at `step` of a path that shortens it by 1e-5 of its length
/// and turns its end i by 3e-4 rad per step: the end i section cracks and crushes through in
/// bending (curvature 4 theta_i / L0 there, twice the far end's).
LocalVector cracking_path(const MortarLocalBeam& beam, int step) {
  LocalVector deformation = LocalVector::Zero();
  deformation[0] = -1e-5 * step * beam.length();
  deformation[2] = 3e-4 * step;
  return deformation;
}

TEST(LocalBeam, FallsBackToAUniformAxialStrainWhereASofteningSectionHasNoEqualForceState) {
  // Along the cracking path the equal-force solve fails once the end section has softened
  // past its peak (found at step 76: the element returned false there before the fallback,
  // and the run stopped, as the small BRB of case 1 did at -43 dy). Reference: the
  // displacement-based beam's definition, e0_k = u / L0 at every point and N = sum_k w_k N_k
  // by virtual work, and its tangent by central differences.
  MortarLocalBeam beam = small_brb_mortar_beam();
  // a softening section may have several equal-force states: the solve starts from the
  // committed strains, never from a predicted one (corot_beam_3d.hpp)
  EXPECT_FALSE(beam.axial_predictor());
  beam.set_axial_predictor(true);
  EXPECT_FALSE(beam.axial_predictor());
  LocalVector force;
  LocalMatrix tangent;
  std::string failure;
  int switched_at = 0;
  for (int step = 1; step <= 120 && switched_at == 0; ++step) {
    ASSERT_TRUE(beam.evaluate(cracking_path(beam, step), force, tangent, failure))
        << "step " << step << ": " << failure;
    if (beam.axial_strain_field() == AxialStrainField::uniform)
      switched_at = step;
    else
      beam.commit();
  }
  ASSERT_GT(switched_at, 1) << "the path never needed the fallback";
  EXPECT_EQ(beam.committed_axial_strain_field(), AxialStrainField::equilibrated);

  const auto expect_uniform_state = [&](const LocalVector& deformation) {
    double virtual_work_force = 0.0;
    for (std::size_t k = 0; k < beam.sections().size(); ++k) {
      EXPECT_DOUBLE_EQ(beam.axial_strains()[k], deformation[0] / beam.length());
      virtual_work_force +=
          beam.integration().weights[k] * beam.sections()[k].last_response().force[0];
    }
    EXPECT_NEAR(force[0], virtual_work_force, 1e-12 * std::abs(virtual_work_force));
  };
  const LocalVector at_switch = cracking_path(beam, switched_at);
  expect_uniform_state(at_switch);

  // Within the trial it stays (a Newton attempt sees one form): back at the committed
  // deformation, which has an equal-force state, the beam is still uniform.
  ASSERT_TRUE(beam.evaluate(cracking_path(beam, switched_at - 1), force, tangent, failure));
  EXPECT_EQ(beam.axial_strain_field(), AxialStrainField::uniform);
  // Reverting drops the fallback with the trial: the committed state is equilibrated again.
  beam.revert_to_committed();
  EXPECT_EQ(beam.axial_strain_field(), AxialStrainField::equilibrated);
  ASSERT_TRUE(beam.evaluate(cracking_path(beam, switched_at - 1), force, tangent, failure));
  EXPECT_EQ(beam.axial_strain_field(), AxialStrainField::equilibrated);

  // Committed, it stays: the beam goes on along the path in the uniform form.
  ASSERT_TRUE(beam.evaluate(at_switch, force, tangent, failure)) << failure;
  ASSERT_EQ(beam.axial_strain_field(), AxialStrainField::uniform);
  beam.commit();
  EXPECT_EQ(beam.committed_axial_strain_field(), AxialStrainField::uniform);
  for (int step = switched_at + 1; step <= switched_at + 10; ++step) {
    ASSERT_TRUE(beam.evaluate(cracking_path(beam, step), force, tangent, failure)) << failure;
    EXPECT_EQ(beam.axial_strain_field(), AxialStrainField::uniform);
    beam.commit();
  }
  const LocalVector trial = cracking_path(beam, switched_at + 11);
  ASSERT_TRUE(beam.evaluate(trial, force, tangent, failure)) << failure;
  expect_uniform_state(trial);
  const auto force_of = [&](const LocalVector& deformation) {
    LocalVector f;
    LocalMatrix unused;
    std::string why;
    EXPECT_TRUE(beam.evaluate(deformation, f, unused, why)) << why;
    return f;
  };
  const Eigen::MatrixXd numeric = test::central_difference_jacobian(force_of, trial, 1e-8);
  EXPECT_LT(test::relative_difference(tangent, numeric), 1e-6);
}

TEST(LocalBeam, TheEndForcesWorkIsBookedThroughTheSwitchToAUniformAxialStrain) {
  // Reference: energy conservation of the element, with the external work summed by the
  // trapezoidal rule as the solvers sum it: sum over the committed steps of
  // (f_c + f_t) . (d_t - d_c) / 2 must equal stored + dissipated + integration misfit
  // (ElementEnergy). In either form alone it does to round-off (the trapezoidal identity at
  // the points, N_k = N or e0_k = u / L0); the step that switches takes work at the points
  // that the end forces did not do, which the beam books with its misfit. Without that
  // booking the difference from the switch on is 8.4 N mm, 1.7e-3 of the gross work.
  MortarLocalBeam beam = small_brb_mortar_beam();
  LocalVector force, committed_force = LocalVector::Zero();
  LocalVector committed_deformation = LocalVector::Zero();
  LocalMatrix tangent;
  std::string failure;
  double work = 0.0, gross = 0.0;
  bool switched = false;
  for (int step = 1; step <= 100; ++step) {
    const LocalVector deformation = cracking_path(beam, step);
    ASSERT_TRUE(beam.evaluate(deformation, force, tangent, failure)) << failure;
    const double increment =
        0.5 * (committed_force + force).dot(deformation - committed_deformation);
    work += increment;
    gross += std::abs(increment);
    beam.commit();
    committed_force = force;
    committed_deformation = deformation;
    switched = switched || beam.committed_axial_strain_field() == AxialStrainField::uniform;
    const ElementEnergy energy = beam.energy();
    EXPECT_NEAR(work, energy.stored + energy.dissipated + energy.integration_misfit, 1e-9 * gross)
        << "step " << step;
  }
  EXPECT_TRUE(switched);
}

} // namespace
} // namespace brb::element
