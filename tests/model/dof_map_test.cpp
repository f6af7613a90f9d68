// DofMap: master-slave elimination of restraints, planar models, equal-DOF and rigid
// diaphragm constraints. References: the constraint equations themselves (rigid-body
// kinematics of a slab, u_s = u_m + rz_m e_z x arm) and T^T M T computed by hand.
#include "brb/element/zero_length_spring.hpp"
#include "brb/model/assembler.hpp"
#include "brb/model/dof_map.hpp"

#include <gtest/gtest.h>

#include <memory>

namespace brb::model {
namespace {

TEST(DofMap, RestrainedDofHaveNoEquation) {
  Model model;
  const int base = model.add_node({0, 0, 0});
  const int top = model.add_node({0, 0, 1000});
  model.fix_all(base);
  const DofMap map = DofMap::build(model, 3);
  EXPECT_EQ(map.equation_count(), 6);
  for (int dof = 0; dof < 6; ++dof) {
    EXPECT_TRUE(map.terms(Model::global_dof(base, static_cast<Dof>(dof))).empty());
    EXPECT_EQ(map.independent_equation(Model::global_dof(top, static_cast<Dof>(dof))), dof);
  }
}

TEST(DofMap, PlanarModelKeepsUxUzRy) {
  Model model;
  model.add_node({0, 0, 0});
  model.add_node({1000, 0, 0});
  const DofMap map = DofMap::build(model, 2);
  EXPECT_EQ(map.equation_count(), 6);
  for (int node = 0; node < 2; ++node) {
    for (const Dof dof : {uy, rx, rz})
      EXPECT_TRUE(map.terms(Model::global_dof(node, dof)).empty());
    for (const Dof dof : {ux, uz, ry})
      EXPECT_GE(map.independent_equation(Model::global_dof(node, dof)), 0);
  }
}

TEST(DofMap, EqualDofChainsResolveToTheFirstMaster) {
  Model model;
  const int a = model.add_node({0, 0, 0});
  const int b = model.add_node({1000, 0, 0});
  const int c = model.add_node({2000, 0, 0});
  model.add_equal_dof({a, b, {ux}});
  model.add_equal_dof({b, c, {ux}});
  const DofMap map = DofMap::build(model, 3);
  EXPECT_EQ(map.equation_count(), 18 - 2);
  const auto terms = map.terms(Model::global_dof(c, ux));
  ASSERT_EQ(terms.size(), 1u);
  EXPECT_EQ(terms[0].equation, map.independent_equation(Model::global_dof(a, ux)));
  EXPECT_DOUBLE_EQ(terms[0].factor, 1.0);
}

TEST(DofMap, ConstraintErrorsAreReported) {
  // a model of three free nodes a, b, c (Model is not copyable: built afresh per case)
  const auto nodes = [](Model& model) {
    model.add_node({0, 0, 0});
    model.add_node({1000, 0, 0});
    model.add_node({0, 1000, 0});
  };
  const int a = 0, b = 1, c = 2;
  Model cycle;
  nodes(cycle);
  cycle.add_equal_dof({a, b, {ux}});
  cycle.add_equal_dof({b, a, {ux}});
  EXPECT_THROW(DofMap::build(cycle, 3), std::invalid_argument);
  Model twice;
  nodes(twice);
  twice.add_equal_dof({a, b, {ux}});
  twice.add_equal_dof({c, b, {ux}});
  EXPECT_THROW(DofMap::build(twice, 3), std::invalid_argument);
  Model restrained;
  nodes(restrained);
  restrained.fix(b, ux);
  restrained.add_equal_dof({a, b, {ux}});
  EXPECT_THROW(DofMap::build(restrained, 3), std::invalid_argument);
  Model planar;
  nodes(planar);
  planar.add_rigid_diaphragm({a, {b}});
  EXPECT_THROW(DofMap::build(planar, 2), std::invalid_argument);
  EXPECT_THROW(DofMap::build(planar, 1), std::invalid_argument);
}

TEST(DofMap, RigidDiaphragmMovesSlavesAsARigidSlab) {
  Model model;
  const int master = model.add_node({100, 200, 3000});
  const int slave = model.add_node({400, -300, 3000}); // arm (300, -500)
  model.add_rigid_diaphragm({master, {slave}});
  const DofMap map = DofMap::build(model, 3);
  EXPECT_EQ(map.equation_count(), 12 - 3);
  Eigen::VectorXd q = Eigen::VectorXd::Zero(map.equation_count());
  const double u = 1.5, v = -2.0, theta = 1e-3;
  q[map.independent_equation(Model::global_dof(master, ux))] = u;
  q[map.independent_equation(Model::global_dof(master, uy))] = v;
  q[map.independent_equation(Model::global_dof(master, rz))] = theta;
  const Eigen::VectorXd full = map.expand(q);
  EXPECT_DOUBLE_EQ(full[Model::global_dof(slave, ux)], u - (-500.0) * theta);
  EXPECT_DOUBLE_EQ(full[Model::global_dof(slave, uy)], v + 300.0 * theta);
  EXPECT_DOUBLE_EQ(full[Model::global_dof(slave, rz)], theta);
  // out-of-plane DOF of the slave stay its own
  EXPECT_GE(map.independent_equation(Model::global_dof(slave, uz)), 0);
}

TEST(DofMap, ReducedMassOfADiaphragmHasTheSlabInertia) {
  // Two slave masses m at (+-a, 0) about the master: T^T M T gives 2m on ux, uy and the
  // rotational inertia 2 m a^2 on rz (and no coupling, by symmetry).
  Model model;
  const double m = 3.0, a = 2000.0;
  const int master = model.add_node({0, 0, 0});
  const int left = model.add_node({-a, 0, 0});
  const int right = model.add_node({a, 0, 0});
  model.add_mass(left, {m, m, 0, 0, 0, 0});
  model.add_mass(right, {m, m, 0, 0, 0, 0});
  model.add_rigid_diaphragm({master, {left, right}});
  const DofMap map = DofMap::build(model, 3);
  const Eigen::MatrixXd mass = Eigen::MatrixXd(map.reduced_mass(model));
  const int eu = map.independent_equation(Model::global_dof(master, ux));
  const int ev = map.independent_equation(Model::global_dof(master, uy));
  const int er = map.independent_equation(Model::global_dof(master, rz));
  EXPECT_DOUBLE_EQ(mass(eu, eu), 2 * m);
  EXPECT_DOUBLE_EQ(mass(ev, ev), 2 * m);
  EXPECT_DOUBLE_EQ(mass(er, er), 2 * m * a * a);
  EXPECT_DOUBLE_EQ(mass(ev, er), 0.0);
  EXPECT_DOUBLE_EQ(mass(eu, er), 0.0);
  // ground influence along X: every free translation along X moves by 1, the slab does not turn
  const Eigen::VectorXd r = map.ground_influence(Eigen::Vector3d::UnitX());
  EXPECT_DOUBLE_EQ(r[eu], 1.0);
  EXPECT_DOUBLE_EQ(r[ev], 0.0);
  EXPECT_DOUBLE_EQ(r[er], 0.0);
}

TEST(Assembler, CongruentTangentOfAConstrainedSpring) {
  // A spring k between a fixed node and a slave of a diaphragm at arm (0, a): the master's
  // rz sees k a^2 and couples to ux by -k a (T^T K T with u_s = u_m - a rz_m).
  Model model;
  const double k = 50.0, a = 400.0;
  const int ground = model.add_node({0, a, -1000});
  const int master = model.add_node({0, 0, 0});
  const int slave = model.add_node({0, a, 0});
  model.fix_all(ground);
  model.add_rigid_diaphragm({master, {slave}});
  model.add_element(std::make_unique<element::ZeroLengthSpring>(
      std::array<int, 2>{ground, slave}, model.coordinates(ground), model.coordinates(slave),
      element::SpringStiffness{k, 0, 0, 0, 0, 0}));
  const DofMap map = DofMap::build(model, 3);
  Assembler assembler(model, map);
  std::string failure;
  ASSERT_TRUE(assembler.assemble(initial_configuration(model), true, failure)) << failure;
  const Eigen::MatrixXd tangent = Eigen::MatrixXd(assembler.reduced_tangent());
  const int eu = map.independent_equation(Model::global_dof(master, ux));
  const int er = map.independent_equation(Model::global_dof(master, rz));
  EXPECT_NEAR(tangent(eu, eu), k, 1e-12);
  EXPECT_NEAR(tangent(eu, er), -k * a, 1e-9);
  EXPECT_NEAR(tangent(er, er), k * a * a, 1e-6);
}

} // namespace
} // namespace brb::model
