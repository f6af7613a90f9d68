// Node-to-surface contact at a corner of the master surface (node_to_surface_contact.hpp): a
// slave node in a concave corner (valley) of an L-shaped master surface touches both faces.
// References: two independent penalties, N_i = k_N <-g_i> along each face's normal with
// k_N = penalty x tributary area (BRB_SOURCE_FACTS section 4); central differences of the
// stored energy; Coulomb sliding, whose friction work is kappa N x slid distance; the energy
// balance of the contact (work of its forces = change of stored energy + friction work); and
// at a convex corner, the single penalty of the nearest face (the shortest way out).
#include "brb/solid/node_to_surface_contact.hpp"

#include "support/contact_checks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace brb::solid {
namespace {

/// Master faces of 10 x 10 mm along y (y in [0, 10 faces]): a floor z = 0 (x in [0, 10],
/// outward +z) and a wall x = 0 (z in [0, 10], outward +x) meeting in the valley's crease
/// x = z = 0, so the master body fills x < 0 or z < 0. Slave face: nodes 0 and 1 on the
/// crease (y = 5 and 6), nodes 2 and 3 3 mm out along (1, 0, 1), open.
struct Valley {
  static constexpr int kFaces = 3;
  Eigen::Matrix3Xd nodes;
  std::vector<QuadFace> master, slave;
  int first_slave = 0;

  Valley() {
    const int columns = kFaces + 1; // crease, floor's outer edge and wall's top, per station
    nodes.resize(3, 3 * columns + 4);
    for (int j = 0; j < columns; ++j) {
      const double y = 10.0 * j;
      nodes.col(j) = Eigen::Vector3d(0, y, 0);                // crease
      nodes.col(columns + j) = Eigen::Vector3d(10, y, 0);     // floor's outer edge
      nodes.col(2 * columns + j) = Eigen::Vector3d(0, y, 10); // wall's top
    }
    for (int j = 0; j < kFaces; ++j) {
      master.push_back({j, columns + j, columns + j + 1, j + 1});         // floor: +x, +y: +z
      master.push_back({j, j + 1, 2 * columns + j + 1, 2 * columns + j}); // wall: +y, +z: +x
    }
    first_slave = 3 * columns;
    const int s = first_slave;
    nodes.col(s) = Eigen::Vector3d(0, 5, 0);
    nodes.col(s + 1) = Eigen::Vector3d(0, 6, 0);
    nodes.col(s + 2) = Eigen::Vector3d(3, 6, 3);
    nodes.col(s + 3) = Eigen::Vector3d(3, 5, 3);
    slave.push_back({s, s + 1, s + 2, s + 3});
  }

  int dof_count() const { return static_cast<int>(3 * nodes.cols()); }
  /// k_N of each slave node: penalty x a quarter of the slave rectangle's area (1 x sqrt(18)).
  static double normal_stiffness(double penalty) { return penalty * std::sqrt(18.0) / 4.0; }

  Eigen::VectorXd slave_moved(const Eigen::Vector3d& shift) const {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(dof_count());
    for (int k = 0; k < 4; ++k)
      u.segment<3>(3 * (first_slave + k)) = shift;
    return u;
  }
};

NodeToSurfaceContactSettings settings_with(double penalty, double ratio, double kappa) {
  NodeToSurfaceContactSettings settings;
  settings.normal_penalty = penalty;
  settings.tangential_stiffness_ratio = ratio;
  settings.friction_coefficient = kappa;
  settings.search_distance = 1.0;
  return settings;
}

using brb::testing::contact_force_at;
using brb::testing::expect_force_is_the_energy_gradient;

TEST(NodeToSurfaceContactCorner, ANodeInAValleyIsPushedOutOfEachFaceByItsOwnPenalty) {
  // The crease nodes pressed 0.03 mm behind the wall and 0.02 mm under the floor: both
  // projections lie just beyond the faces' edges at the crease (by the other penetration).
  // Theory: two independent penalties, on each crease node -k_N (0.03, 0, 0.02) (internal-force
  // sense: the floor pushes it up by k_N 0.02, the wall out by k_N 0.03); the open nodes
  // none. Then, moved in stick (kappa 0.5: |u_T| <= 0.0025 mm < kappa g = 0.01 mm), the force
  // is the gradient of the stored energy sum_i 1/2 k_N g_i^2 + 1/2 |T_i|^2 / k_T (central
  // differences, step 1e-6 mm, on every DOF of the slave and master).
  const Valley valley;
  const double penalty = 1000.0, k_N = Valley::normal_stiffness(penalty);
  NodeToSurfaceContact contact(valley.nodes, valley.slave, valley.master,
                               settings_with(penalty, 1.0, 0.5));
  Eigen::VectorXd u = valley.slave_moved({-0.03, 0.0, -0.02});
  Eigen::VectorXd force = contact_force_at(contact, u);
  EXPECT_EQ(contact.statistics().nodes_in_contact, 2);
  EXPECT_EQ(contact.statistics().nodes_in_corners, 2);
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d f = force.segment<3>(3 * (valley.first_slave + k));
    EXPECT_NEAR(f.x(), -k_N * 0.03, 1e-10);
    EXPECT_NEAR(f.y(), 0.0, 1e-12);
    EXPECT_NEAR(f.z(), -k_N * 0.02, 1e-10);
    const NodeContactState& state = contact.trial_states(0)[static_cast<std::size_t>(k)];
    ASSERT_EQ(state.contact_count, 2);
    EXPECT_NEAR(state.contact(0).normal.z(), 1.0, 1e-15); // the nearest face first: the floor
    EXPECT_NEAR(state.contact(1).normal.x(), 1.0, 1e-15);
  }
  for (int k = 2; k < 4; ++k)
    EXPECT_EQ(force.segment<3>(3 * (valley.first_slave + k)).norm(), 0.0);
  contact.commit();
  EXPECT_NEAR(contact.stored_energy(), 2 * 0.5 * k_N * (0.03 * 0.03 + 0.02 * 0.02), 1e-12);

  u = valley.slave_moved({-0.029, 0.002, -0.0185});
  force = contact_force_at(contact, u);
  ASSERT_EQ(contact.statistics().nodes_slipping, 0);
  ASSERT_EQ(contact.statistics().nodes_in_corners, 2);
  expect_force_is_the_energy_gradient(contact, u, force);
}

TEST(NodeToSurfaceContactCorner, SlidingAlongAValleyDissipatesExactlyTheWorkOfTheForces) {
  // The crease nodes pressed 0.03 mm into the wall and 0.02 mm into the floor, then slid 20 mm
  // along the crease in 0.005 mm steps (across two face boundaries), the master at rest.
  // References: the contact's energy balance, W = sum over steps of the trapezoidal work of its
  // forces on the slave nodes = change of stored energy + friction work, exact in steady
  // sliding (constant forces); and Coulomb, each face's friction kappa N_i opposing the slide,
  // so the friction work is kappa (N_floor + N_wall) x distance per node. With one contact per
  // node (the nearest face, the floor) whose stick anchor slips onto the wall at the crease,
  // the anchor lands off its target and the friction work exceeds W.
  const Valley valley;
  const double penalty = 1000.0, kappa = 0.3, k_N = Valley::normal_stiffness(penalty);
  const double wall = 0.03, floor = 0.02, step = 0.005;
  NodeToSurfaceContact contact(valley.nodes, valley.slave, valley.master,
                               settings_with(penalty, 1.0, kappa));
  Eigen::VectorXd u = valley.slave_moved({-wall, 0.0, -floor});
  Eigen::VectorXd force = contact_force_at(contact, u);
  contact.commit();
  const int sliding_from = 10; // stick limits kappa g = 0.006 and 0.009 mm: 2 steps
  const int steps = 4000;
  double work = 0.0, stored_start = 0.0, dissipated_start = 0.0;
  for (int n = 1; n <= steps; ++n) {
    const Eigen::VectorXd u_next = valley.slave_moved({-wall, step * n, -floor});
    const Eigen::VectorXd force_next = contact_force_at(contact, u_next);
    ASSERT_EQ(contact.statistics().nodes_in_contact, 2) << "step " << n;
    contact.commit();
    if (n > sliding_from) {
      ASSERT_EQ(contact.statistics().nodes_slipping, 2) << "step " << n;
      work += 0.5 * (force + force_next).dot(u_next - u);
    } else if (n == sliding_from) {
      stored_start = contact.stored_energy();
      dissipated_start = contact.dissipated_energy();
    }
    u = u_next;
    force = force_next;
  }
  const double friction = contact.dissipated_energy() - dissipated_start;
  const double distance = step * (steps - sliding_from);
  EXPECT_NEAR(friction, 2 * kappa * k_N * (wall + floor) * distance, 1e-9 * friction);
  EXPECT_NEAR(friction + contact.stored_energy() - stored_start, work, 1e-9 * work);
  // each face holds its own Coulomb force on the sliding node: -kappa N_i along y each
  for (int k = 0; k < 2; ++k)
    EXPECT_NEAR(force[3 * (valley.first_slave + k) + 1], kappa * k_N * (wall + floor),
                1e-9 * kappa * k_N);
}

TEST(NodeToSurfaceContactCorner, ANodeInsideAConvexCornerKeepsOnlyTheNearestFace) {
  // A box's convex edge along y: top face z = 0 (x in [-10, 0], outward +z) and side face x = 0
  // (z in [-10, 0], outward +x), the body in x < 0 and z < 0. A slave node 0.03 mm inside the
  // side and 0.02 mm under the top projects inside both faces; the shortest way out of the
  // body is through the top: theory, the single penalty -k_N 0.02 along z (each face's centroid
  // lies behind the other's plane: no valley).
  Eigen::Matrix3Xd nodes(3, 10);
  nodes << -10, 0, 0, -10, 0, 0, 0, 0, /* slave */ -0.03, -0.03, //
      0, 0, 10, 10, 0, 10, 10, 0, /* slave */ 5, 6,              //
      0, 0, 0, 0, -10, -10, 0, 0, /* slave */ -0.02, -0.02;
  const std::vector<QuadFace> master{{0, 1, 2, 3}, {4, 5, 6, 7}};
  // a slave face with two nodes at the corner and two far outside (open)
  Eigen::Matrix3Xd all(3, 12);
  all << nodes, Eigen::Vector3d(5, 6, 5), Eigen::Vector3d(5, 5, 5);
  const std::vector<QuadFace> slave{{8, 9, 10, 11}};
  const double penalty = 1000.0;
  NodeToSurfaceContact contact(all, slave, master, settings_with(penalty, 1.0, 0.5));
  const Eigen::VectorXd force = contact_force_at(contact, Eigen::VectorXd::Zero(36));
  EXPECT_EQ(contact.statistics().nodes_in_contact, 2);
  EXPECT_EQ(contact.statistics().nodes_in_corners, 0);
  const double k_N = contact.normal_stiffness(0)[0];
  EXPECT_NEAR(k_N, penalty * 0.25 * std::sqrt(5.03 * 5.03 + 5.02 * 5.02), 1e-9); // 1 x diagonal
  for (int node : {8, 9}) {
    EXPECT_NEAR(force[3 * node + 2], -k_N * 0.02, 1e-12 * k_N * 0.02); // round-off
    EXPECT_NEAR(force.segment<2>(3 * node).norm(), 0.0, 1e-12 * k_N * 0.02);
  }
}

TEST(NodeToSurfaceContactCorner, AnEndingContactCreditsItsSpringEnergyAsFrictionWork) {
  // A crease node pressed into both faces, moved in stick (kappa 0.5) along y by 0.004 mm, then
  // lifted out of the corner in one step. Theory: T = k_T 0.004 on each face (stick), stored
  // sum 1/2 |T|^2 / k_T = 2 x 1/2 k_T 0.004^2 per node; lifted straight off, T does no work, so
  // the balance (work = stored + friction work) needs that energy credited as friction work
  // when the contacts end: dissipated = 2 nodes x 2 faces x 1/2 k_T 0.004^2.
  const Valley valley;
  const double penalty = 1000.0, ratio = 1.5, k_T = ratio * Valley::normal_stiffness(penalty);
  NodeToSurfaceContact contact(valley.nodes, valley.slave, valley.master,
                               settings_with(penalty, ratio, 0.5));
  contact_force_at(contact, valley.slave_moved({-0.03, 0.0, -0.02}));
  contact.commit();
  contact_force_at(contact, valley.slave_moved({-0.03, 0.004, -0.02}));
  ASSERT_EQ(contact.statistics().nodes_slipping, 0);
  ASSERT_EQ(contact.statistics().nodes_in_corners, 2);
  contact.commit();
  EXPECT_EQ(contact.dissipated_energy(), 0.0);
  contact_force_at(contact, valley.slave_moved({0.1, 0.004, 0.1}));
  ASSERT_EQ(contact.statistics().nodes_in_contact, 0);
  contact.commit();
  EXPECT_EQ(contact.stored_energy(), 0.0);
  EXPECT_NEAR(contact.dissipated_energy(), 4 * 0.5 * k_T * 0.004 * 0.004,
              1e-12 * k_T * 0.004 * 0.004);
}

TEST(NodeToSurfaceContactCorner, CornerContactsDoNotDependOnTheThreadCount) {
  // Two-pass contact (the L's nodes also on the slave face) sliding along the valley into
  // slip: forces and friction work bitwise equal for 1, 2 and 3 threads (each node writes its
  // own record, summed in node order).
  const Valley valley;
  NodeToSurfaceContactSettings settings = settings_with(1000.0, 1.0, 0.3);
  settings.two_pass = true;
  std::vector<Eigen::VectorXd> reference;
  double reference_dissipation = 0.0;
  for (int threads : {1, 2, 3}) {
    NodeToSurfaceContact contact(valley.nodes, valley.slave, valley.master, settings);
    contact.set_threads(threads);
    std::vector<Eigen::VectorXd> forces;
    for (int n = 0; n <= 40; ++n) {
      forces.push_back(contact_force_at(contact, valley.slave_moved({-0.03, 0.005 * n, -0.02})));
      contact.commit();
    }
    if (threads == 1) {
      reference = forces;
      reference_dissipation = contact.dissipated_energy();
      EXPECT_EQ(contact.statistics().nodes_in_corners, 2);
      EXPECT_GT(reference_dissipation, 0.0);
      continue;
    }
    for (std::size_t k = 0; k < forces.size(); ++k)
      EXPECT_TRUE(forces[k] == reference[k]) << threads << " threads, step " << k;
    EXPECT_EQ(contact.dissipated_energy(), reference_dissipation);
  }
}

} // namespace
} // namespace brb::solid
