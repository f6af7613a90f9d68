// UniaxialSpring: a uniaxial law per DOF of given axes between two nodes.
#include "brb/element/frame_element_specs.hpp"
#include "brb/element/rotation.hpp"
#include "brb/element/uniaxial_spring.hpp"
#include "brb/material/parameter_error.hpp"

#include "support/finite_difference.hpp"
#include "support/steel_fixtures.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace brb::element {
namespace {

constexpr std::array<double, 6> kStiffness{1e4, 2e3, 3e3, 5e6, 7e6, 11e6}; // N/mm, N mm/rad

/// Skew orthonormal axes.
const Matrix3 kAxes = rotation_from_vector(Vector3(0.4, -0.7, 0.25));

struct Evaluation {
  Eigen::VectorXd force;
  Eigen::MatrixXd tangent;
};

Evaluation evaluate(Element& element, const std::vector<NodeConfiguration>& nodes) {
  Evaluation result;
  std::string failure;
  EXPECT_TRUE(element.evaluate(nodes, result.force, result.tangent, failure)) << failure;
  return result;
}

std::vector<NodeConfiguration> moved(const std::vector<NodeConfiguration>& base,
                                     const Eigen::VectorXd& motion) {
  std::vector<NodeConfiguration> nodes = base;
  for (int n = 0; n < 2; ++n) {
    nodes[n].position += motion.segment<3>(6 * n);
    nodes[n].rotation = rotation_from_vector(motion.segment<3>(6 * n + 3)) * nodes[n].rotation;
  }
  return nodes;
}

UniaxialSpringSpec elastic_spec(const Matrix3& axes) {
  UniaxialSpringSpec spec{{0, 1}, {}, axes};
  for (std::size_t dof = 0; dof < 6; ++dof)
    spec.dofs[dof] = SpringDofSpec{ElasticLawParameters{kStiffness[dof]}};
  return spec;
}

/// Steel used as force-deformation: "E" = k (N/mm), "fy" = Fy (N), no hardening (elastic-
/// perfectly plastic) unless asked.
material::SteelParameters spring_steel(double stiffness, double yield_force,
                                       double kinematic = 0.0) {
  material::SteelParameters steel;
  steel.youngs_modulus = stiffness;
  steel.yield_stress = yield_force;
  steel.kinematic_hardening = kinematic;
  return steel;
}

TEST(UniaxialSpring, ElasticLawsActPerDofOfTheSpringAxes) {
  // Reference: Hooke per DOF in the spring's axes Q: f_j = Q diag(k) Q^T s = -f_i, and for
  // a small relative rotation theta (1e-7 rad) moments Q diag(k_r) Q^T theta up to O(theta)
  // (1e-6 relative); stored energy 1/2 sum k delta^2.
  const Vector3 xi(10.0, 20.0, 30.0), xj(10.0, 20.0, 30.5);
  const auto spring = make_uniaxial_spring(elastic_spec(kAxes), xi, xj);
  const Vector3 stretch(0.1, -0.2, 0.3), theta(2e-7, -1e-7, 3e-7);
  const std::vector<NodeConfiguration> nodes{{xi, Matrix3::Identity()},
                                             {xj + stretch, rotation_from_vector(theta)}};
  const Evaluation result = evaluate(*spring, nodes);
  const Vector3 k_u(kStiffness[0], kStiffness[1], kStiffness[2]);
  const Vector3 k_r(kStiffness[3], kStiffness[4], kStiffness[5]);
  const Vector3 force = kAxes * k_u.asDiagonal() * kAxes.transpose() * stretch;
  const Vector3 moment = kAxes * k_r.asDiagonal() * kAxes.transpose() * theta;
  EXPECT_LT((result.force.segment<3>(6) - force).norm(), 1e-12 * force.norm());
  EXPECT_LT((result.force.segment<3>(0) + force).norm(), 1e-12 * force.norm());
  EXPECT_LT((result.force.segment<3>(9) - moment).norm(), 1e-6 * moment.norm());
  EXPECT_LT((result.force.segment<3>(3) + moment).norm(), 1e-6 * moment.norm());
  const Vector3 delta_u = kAxes.transpose() * stretch, delta_r = kAxes.transpose() * theta;
  const double energy =
      0.5 * (delta_u.dot(k_u.asDiagonal() * delta_u) + delta_r.dot(k_r.asDiagonal() * delta_r));
  EXPECT_NEAR(spring->energy().stored, energy, 1e-9 * energy);
  EXPECT_EQ(spring->energy().dissipated, 0.0);
  // the elastic laws reproduce ZeroLengthSpring's tangent at the reference state exactly
  EXPECT_LT((evaluate(*spring, {{xi, Matrix3::Identity()}, {xj, Matrix3::Identity()}})
                 .tangent.block<3, 3>(6, 6) -
             kAxes * k_u.asDiagonal() * kAxes.transpose())
                .norm(),
            1e-9);
}

TEST(UniaxialSpring, SteelLawAsForceDeformationYieldsAtTheYieldForce) {
  // Reference: an elastic-perfectly plastic spring (steel law with E = k, fy = Fy, no
  // hardening) carries at most Fy; cycling 0 -> 3 dy -> -3 dy -> 3 dy (dy = Fy / k) it
  // dissipates Fy times the plastic travel 2 dy + 4 dy + 4 dy = 10 Fy dy.
  const double stiffness = 5000.0, yield_force = 2.0e4, yield_deformation = yield_force / stiffness;
  UniaxialSpringSpec spec{{0, 1}, {}, Matrix3::Identity()};
  spec.dofs[1] = SpringDofSpec{spring_steel(stiffness, yield_force)}; // uy
  spec.dofs[5] = SpringDofSpec{spring_steel(3.0e9, 4.0e7)};           // rz: moment-rotation
  const auto spring = make_uniaxial_spring(spec, Vector3::Zero(), Vector3::Zero());
  double peak = 0.0, trough = 0.0, peak_moment = 0.0;
  const int steps = 60;
  const auto drive = [&](double from, double to) {
    for (int step = 1; step <= steps; ++step) {
      const double deformation = from + (to - from) * step / steps;
      const double twist = deformation / yield_deformation * (4.0e7 / 3.0e9);
      const std::vector<NodeConfiguration> nodes{
          {Vector3::Zero(), Matrix3::Identity()},
          {Vector3(0.0, deformation, 0.0), rotation_from_vector(Vector3(0.0, 0.0, twist))}};
      const Evaluation result = evaluate(*spring, nodes);
      spring->commit();
      peak = std::max(peak, result.force[7]);
      trough = std::min(trough, result.force[7]);
      peak_moment = std::max(peak_moment, result.force[11]);
    }
  };
  drive(0.0, 3.0 * yield_deformation);
  drive(3.0 * yield_deformation, -3.0 * yield_deformation);
  drive(-3.0 * yield_deformation, 3.0 * yield_deformation);
  EXPECT_NEAR(peak, yield_force, 1e-9 * yield_force);
  EXPECT_NEAR(trough, -yield_force, 1e-9 * yield_force);
  // the rotation is about z alone, so the conjugate moment is the nodal moment: My exactly
  EXPECT_NEAR(peak_moment, 4.0e7, 1e-9 * 4.0e7);
  const double rotational_dissipation = 10.0 * 4.0e7 * (4.0e7 / 3.0e9);
  const double expected = 10.0 * yield_force * yield_deformation + rotational_dissipation;
  EXPECT_NEAR(spring->energy().dissipated, expected, 1e-9 * expected);
  EXPECT_NEAR(spring->dof_force()[1], yield_force, 1e-9 * yield_force);
}

TEST(UniaxialSpring, TangentMatchesFiniteDifferencesAtFiniteRotations) {
  // Reference: central differences of the forces over translations and spins, for elastic
  // laws and for hardening steel laws loaded past yield (consistent tangent of the law).
  const Vector3 xi(1.0, 2.0, 3.0), xj(1.0, 2.0, 3.5);
  const std::vector<NodeConfiguration> base{
      {Vector3(1.1, 2.0, 2.9), rotation_from_vector(Vector3(0.3, -0.2, 0.1))},
      {Vector3(0.9, 2.2, 3.6), rotation_from_vector(Vector3(-0.1, 0.4, 0.25))}};

  const auto elastic = make_uniaxial_spring(elastic_spec(kAxes), xi, xj);
  const auto check = [&](UniaxialSpring& spring) {
    const Eigen::MatrixXd analytic = evaluate(spring, base).tangent;
    const auto forces = [&](const Eigen::VectorXd& motion) {
      return evaluate(spring, moved(base, motion)).force;
    };
    const Eigen::MatrixXd numeric =
        test::central_difference_jacobian(forces, Eigen::VectorXd::Zero(12).eval(), 1e-7);
    return test::relative_difference(analytic, numeric);
  };
  EXPECT_LT(check(*elastic), 1e-6);

  UniaxialSpringSpec spec{{0, 1}, {}, kAxes};
  for (std::size_t dof = 0; dof < 6; ++dof) {
    // yield at 1e-3 (mm or rad), far below the base state's deformations: every DOF yields
    spec.dofs[dof] = SpringDofSpec{
        spring_steel(kStiffness[dof], kStiffness[dof] * 1e-3, 0.05 * kStiffness[dof])};
  }
  const auto hysteretic = make_uniaxial_spring(spec, xi, xj);
  EXPECT_LT(check(*hysteretic), 1e-6);
}

TEST(UniaxialSpring, RejectsBadSpecsNamingTheField) {
  const auto field_of = [](const UniaxialSpringSpec& spec) -> std::string {
    try {
      make_uniaxial_spring(spec, Vector3::Zero(), Vector3::Zero());
    } catch (const ParameterError& error) {
      return error.field();
    }
    return "";
  };
  EXPECT_EQ(field_of(UniaxialSpringSpec{{0, 1}, {}, Matrix3::Identity()}), "dofs");
  UniaxialSpringSpec spec = elastic_spec(Matrix3::Identity());
  spec.axes(0, 1) = 0.5;
  EXPECT_EQ(field_of(spec), "axes");
  spec = elastic_spec(Matrix3::Identity());
  spec.dofs[4]->deformation_scale = 0.0;
  EXPECT_EQ(field_of(spec), "dofs.ry");
  spec = elastic_spec(Matrix3::Identity());
  spec.dofs[2]->material = ElasticLawParameters{-5.0};
  EXPECT_EQ(field_of(spec), "E");
}

} // namespace
} // namespace brb::element
