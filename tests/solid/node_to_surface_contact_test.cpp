// Node-to-surface penalty contact with Coulomb friction (node_to_surface_contact.hpp), on
// small surfaces driven by prescribed displacements. References: the penalty law N = k_N <-g>
// with k_N = penalty x tributary area (BRB_SOURCE_FACTS section 4), Coulomb's |T| <= kappa N
// with the elastic stick T = k_T u_T, the friction work kappa N x slip, central differences of
// the stored energy, and objectivity (a rigid rotation of everything rotates the forces).
#include "brb/material/parameter_error.hpp"
#include "brb/solid/node_to_surface_contact.hpp"

#include "support/contact_checks.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <functional>

namespace brb::solid {
namespace {

/// A flat or warped master grid (nx x ny faces of size `spacing` on z = 0, outward +z) and a
/// small square slave face above it (outward -z, facing the master), all in one node list.
struct Pair {
  Eigen::Matrix3Xd nodes;
  std::vector<QuadFace> master, slave;
  std::vector<int> slave_nodes; // the slave face's 4 nodes
  int master_node_count = 0;

  /// lift(i, j): z of master grid node (i, j), for warped faces.
  Pair(int nx, int ny, double spacing, const Eigen::Vector2d& slave_corner, double slave_side,
       double slave_height, const std::function<double(int, int)>& lift = nullptr) {
    master_node_count = (nx + 1) * (ny + 1);
    nodes.resize(3, master_node_count + 4);
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        nodes.col(i + (nx + 1) * j) =
            Eigen::Vector3d(i * spacing, j * spacing, lift ? lift(i, j) : 0.0);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int a = i + (nx + 1) * j;
        master.push_back({a, a + 1, a + nx + 2, a + nx + 1}); // counter-clockwise from +z
      }
    const int s = master_node_count;
    const double x0 = slave_corner.x(), y0 = slave_corner.y(), h = slave_side;
    nodes.col(s) = Eigen::Vector3d(x0, y0, slave_height);
    nodes.col(s + 1) = Eigen::Vector3d(x0, y0 + h, slave_height);
    nodes.col(s + 2) = Eigen::Vector3d(x0 + h, y0 + h, slave_height);
    nodes.col(s + 3) = Eigen::Vector3d(x0 + h, y0, slave_height);
    slave.push_back({s, s + 1, s + 2, s + 3}); // counter-clockwise from -z: outward -z
    slave_nodes = {s, s + 1, s + 2, s + 3};
  }

  int dof_count() const { return static_cast<int>(3 * nodes.cols()); }

  /// Displacement moving the slave face rigidly by `shift`, the master at rest.
  Eigen::VectorXd slave_moved(const Eigen::Vector3d& shift) const {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(dof_count());
    for (int n : slave_nodes)
      u.segment<3>(3 * n) = shift;
    return u;
  }
};

NodeToSurfaceContactSettings settings_with(double penalty, double ratio, double kappa,
                                           double search = 1.0) {
  NodeToSurfaceContactSettings settings;
  settings.normal_penalty = penalty;
  settings.tangential_stiffness_ratio = ratio;
  settings.friction_coefficient = kappa;
  settings.search_distance = search;
  return settings;
}

using brb::testing::contact_force_at;
using brb::testing::expect_force_is_the_energy_gradient;

Eigen::Vector3d node_force(const Eigen::VectorXd& force, int node) {
  return force.segment<3>(3 * node);
}

TEST(NodeToSurfaceContact, SourceContactPairHasNoForceUntilTheGapClosesThenKNTimesPenetration) {
  // BRB_SOURCE_FACTS section 6, contact pair: slave 0.12 mm from the master face, transverse
  // ramp of the slave to 0.25 mm, then held. Theory (section 4): N = k_N <-g>, g = 0.12 - w,
  // k_N = penalty x tributary area = 1000 N/mm^3 x (2 x 2 mm^2 / 4) = 1000 N/mm per node.
  const Pair pair(1, 1, 10.0, {4.0, 4.0}, 2.0, 0.12);
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings_with(1000.0, 1, 0.1));
  for (double k : contact.normal_stiffness(0))
    EXPECT_NEAR(k, 1000.0, 1e-11); // the area by 2 x 2 Gauss points: exact up to round-off
  for (int step = 0; step <= 60; ++step) {
    const double w = 0.25 * std::min(step, 50) / 50.0; // ramp, then held for 10 steps
    const Eigen::VectorXd force = contact_force_at(contact, pair.slave_moved({0.0, 0.0, -w}));
    const double penetration = std::max(0.0, w - 0.12);
    for (int n : pair.slave_nodes) {
      // internal-force sense: the master pushes the slave up, so its entry is -N
      EXPECT_NEAR(node_force(force, n).z(), -1000.0 * penetration, 1e-9) << "w = " << w;
      EXPECT_NEAR(node_force(force, n).head<2>().norm(), 0.0, 1e-12);
    }
    EXPECT_NEAR(force.sum(), 0.0, 1e-9); // equal and opposite on the master face
    EXPECT_EQ(contact.statistics().nodes_in_contact, penetration > 0.0 ? 4 : 0);
    contact.commit();
    EXPECT_NEAR(contact.stored_energy(), 4 * 0.5 * 1000.0 * penetration * penetration, 1e-12);
  }
  EXPECT_DOUBLE_EQ(contact.dissipated_energy(), 0.0); // pressed straight: no slip
}

TEST(NodeToSurfaceContact, ForceIsMinusTheGradientOfTheStoredEnergyInStick) {
  // A warped master (grid nodes lifted by 0.3 sin, 2 x 2 faces) and a slave face pressed
  // 0.05 mm into it, then moved 0.01 mm sideways in stick (kappa 0.5: k_T u = 0.01 k_N <
  // kappa N = 0.025 k_N). The force must be the gradient of the stored energy 1/2 k_N g^2 +
  // 1/2 |T|^2 / k_T with respect to every node of the slave and master faces: checked by
  // central differences (step 1e-6 mm, truncation O(1e-12) relative). Without the tangent
  // plane's rotation term the master forces would be off by ~k_T u g / face ~ 1e-3 of them.
  const Pair pair(2, 2, 5.0, {2.5, 1.0}, 2.0, 0.0,
                  [](int i, int j) { return 0.3 * std::sin(1.1 * i + 0.7 * j * j); });
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings_with(800.0, 1.3, 0.5));
  // The slave face starts on z = 0, the master is warped: first place each slave node
  // 0.05 mm below its own master point (vertical offset chosen per node by a projection).
  Eigen::VectorXd u = Eigen::VectorXd::Zero(pair.dof_count());
  for (int n : pair.slave_nodes) {
    const QuadFace* face = nullptr;
    QuadProjection projection;
    for (const QuadFace& f : pair.master) {
      Eigen::Matrix<double, 3, 4> x;
      for (int a = 0; a < 4; ++a)
        x.col(a) = pair.nodes.col(f[a]);
      const QuadProjection p = project_on_quad(x, pair.nodes.col(n) + Eigen::Vector3d(0, 0, 1));
      if (p.converged && p.inside && (!face || std::abs(p.gap) < std::abs(projection.gap))) {
        face = &f;
        projection = p;
      }
    }
    ASSERT_NE(face, nullptr);
    u.segment<3>(3 * n) =
        projection.point.position - pair.nodes.col(n) - 0.05 * projection.point.normal;
  }
  contact_force_at(contact, u);
  ASSERT_EQ(contact.statistics().nodes_in_contact, 4);
  contact.commit(); // anchors at the first contact points
  for (int n : pair.slave_nodes)
    u.segment<3>(3 * n) += Eigen::Vector3d(0.008, -0.006, 0.0);
  const Eigen::VectorXd force = contact_force_at(contact, u);
  ASSERT_EQ(contact.statistics().nodes_in_contact, 4);
  ASSERT_EQ(contact.statistics().nodes_slipping, 0);
  double tangential = 0.0;
  for (const NodeContactState& s : contact.trial_states(0))
    tangential = std::max(tangential, s.tangential_force.norm());
  ASSERT_GT(tangential, 0.0);

  expect_force_is_the_energy_gradient(contact, u, force);
}

TEST(NodeToSurfaceContact, ForceIsTheEnergyGradientWithTheAnchorOnAnotherFace) {
  // Flat master of two faces meeting at x = 5; a small slave face (x in [4.996, 4.998])
  // touches with its anchors on the first face and is then moved 0.005 mm along x in stick
  // (kappa 0.5, so k_T u = 0.0065 k_N < kappa N = 0.025 k_N): the contact points are on the
  // second face, the anchors stay on the first, and the force is still the gradient of the
  // stored energy.
  const Pair pair(2, 1, 5.0, {4.996, 1.0}, 0.002, 0.0);
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings_with(800.0, 1.3, 0.5));
  Eigen::VectorXd u = pair.slave_moved({0, 0, -0.05});
  contact_force_at(contact, u);
  contact.commit();
  u = pair.slave_moved({0.005, 0, -0.05});
  const Eigen::VectorXd force = contact_force_at(contact, u);
  ASSERT_EQ(contact.statistics().nodes_slipping, 0);
  for (const NodeContactState& state : contact.trial_states(0)) {
    ASSERT_EQ(state.face, 1);
    ASSERT_EQ(state.anchor_face, 0);
    // T = k_T u = 1.3 k_N 0.005, k_N = N / 0.05
    EXPECT_NEAR(state.tangential_force.x() / (1.3 * state.normal_force / 0.05 * 0.005), 1.0, 1e-9);
  }
  expect_force_is_the_energy_gradient(contact, u, force);
}

TEST(NodeToSurfaceContact, SticksWithKTUThenSlidesAtKappaNAndDissipatesKappaNTimesSlip) {
  // Pressed 0.02 mm (N = k_N 0.02 per node), then pushed along x: T = k_T u while below
  // kappa N (Coulomb, BRB_SOURCE_FACTS section 4), then exactly kappa N; the friction work
  // is kappa N x (u - kappa N / k_T) per node. Then pulled back 0.0005 mm: stick again,
  // T = kappa N - k_T 0.0005 (half the force).
  const double penalty = 1000.0, ratio = 2.0, kappa = 0.1, press = 0.02;
  const Pair pair(1, 1, 10.0, {4.0, 4.0}, 2.0, 0.0);
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master,
                               settings_with(penalty, ratio, kappa));
  const double k_N = penalty * 1.0, k_T = ratio * k_N, N = k_N * press;
  contact_force_at(contact, pair.slave_moved({0, 0, -press}));
  contact.commit();
  const double stick_limit = kappa * N / k_T; // 0.001 mm
  for (int step = 1; step <= 40; ++step) {
    const double push = 0.000097 * step; // no step lands on the stick limit itself
    const Eigen::VectorXd force = contact_force_at(contact, pair.slave_moved({push, 0, -press}));
    const double expected = std::min(k_T * push, kappa * N);
    for (int n : pair.slave_nodes) {
      EXPECT_NEAR(node_force(force, n).x(), expected, 1e-10) << "push " << push;
      EXPECT_NEAR(node_force(force, n).z(), -N, 1e-10);
    }
    EXPECT_EQ(contact.statistics().nodes_slipping, push > stick_limit + 1e-12 ? 4 : 0);
    contact.commit();
    const double slip = std::max(0.0, push - stick_limit);
    EXPECT_NEAR(contact.dissipated_energy(), 4 * kappa * N * slip, 1e-12);
  }
  const Eigen::VectorXd back =
      contact_force_at(contact, pair.slave_moved({0.000097 * 40 - 0.0005, 0, -press}));
  for (int n : pair.slave_nodes)
    EXPECT_NEAR(node_force(back, n).x(), kappa * N - k_T * 0.0005, 1e-10);
  EXPECT_EQ(contact.statistics().nodes_slipping, 0);
}

TEST(NodeToSurfaceContact, SlidingAcrossAFaceBoundaryKeepsKappaNWithoutAJump) {
  // Two master faces side by side (x in [0, 10] and [10, 20]); the slave face (x in [7, 8])
  // is pressed and slid 6 mm along x, so every node and every stick anchor crosses x = 10.
  // Coulomb: once sliding, |T| = kappa N at every step, the same on both faces.
  const double penalty = 500.0, press = 0.01, kappa = 0.1;
  const Pair pair(2, 1, 10.0, {7.0, 4.0}, 1.0, 0.0);
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master,
                               settings_with(penalty, 1.0, kappa));
  const double N = penalty * 0.25 * press; // tributary area 1/4 mm^2
  contact_force_at(contact, pair.slave_moved({0, 0, -press}));
  contact.commit();
  std::vector<double> previous(4, 0.0);
  bool sliding = false;
  int sliding_steps = 0;
  double largest_jump = 0.0;
  for (int step = 1; step <= 600; ++step) {
    const Eigen::VectorXd force =
        contact_force_at(contact, pair.slave_moved({0.01 * step, 0, -press}));
    ASSERT_EQ(contact.statistics().nodes_in_contact, 4);
    const bool was_sliding = sliding;
    sliding = sliding || contact.statistics().nodes_slipping == 4;
    sliding_steps += sliding ? 1 : 0;
    for (int k = 0; k < 4; ++k) {
      const double T = node_force(force, pair.slave_nodes[k]).x();
      if (sliding) {
        EXPECT_NEAR(T, kappa * N, 1e-12 * N) << "step " << step;
      }
      if (was_sliding)
        largest_jump = std::max(largest_jump, std::abs(T - previous[k]));
      previous[k] = T;
    }
    EXPECT_NEAR(force.sum(), 0.0, 1e-12);
    contact.commit();
  }
  EXPECT_GE(sliding_steps, 599); // 0.01 mm steps, stick limit kappa N / k_T = 0.001 mm
  EXPECT_LT(largest_jump, 1e-12 * N);
  for (const NodeContactState& state : contact.states(0)) {
    EXPECT_EQ(state.face, 1);        // the contact point crossed to the second face
    EXPECT_EQ(state.anchor_face, 1); // and so did the stick anchor
  }
}

TEST(NodeToSurfaceContact, APenetratingNodeUnderAValleyCreaseIsNotLost) {
  // Two master faces folded into a valley along x = 10 (slopes +-0.1); slave nodes on the
  // crease line, 0.2 mm below it, have their closest points on both faces' extensions 0.02 mm
  // beyond the crease (outside both faces): they are taken by the edge tolerance. Theory:
  // the distance to either face's plane is 0.2 cos(a), tan(a) = 0.1, so N = k_N 0.2 / sqrt(1.01).
  const Pair pair(2, 1, 10.0, {10.0, 4.0}, 1.0, -0.2,
                  [](int i, int) { return i == 1 ? 0.0 : 1.0; });
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings_with(1000, 1, 0.1));
  const Eigen::VectorXd force = contact_force_at(contact, pair.slave_moved({0, 0, 0}));
  EXPECT_EQ(contact.statistics().nodes_in_contact, 4);
  const double k_N = 1000.0 * 0.25;
  for (int k : {0, 1}) { // the slave nodes at x = 10
    const Eigen::Vector3d f = node_force(force, pair.slave_nodes[k]);
    EXPECT_NEAR(f.norm(), k_N * 0.2 / std::sqrt(1.01), 1e-9);
  }
}

TEST(NodeToSurfaceContact, ANodeBesideAConvexEdgeIsNotInContact) {
  // The master face z = 0 (x in [0, 10], y in [0, 4], normal +z) is the top of a body below
  // it. Slave nodes at y = 4.05, 3 mm below its plane, lie beside the body's edge y = 4 (0.025
  // beyond it in natural coordinates, within the edge tolerance), not inside it: a casing
  // node at the mouth once the core has slid out from under it. Theory: open, no force (the
  // extension would report a penetration of 3 mm).
  Eigen::Matrix3Xd nodes(3, 8);
  nodes << 0, 10, 10, 0, 5, 6, 6, 5,      //
      0, 0, 4, 4, 4.05, 4.05, 4.05, 4.05, //
      0, 0, 0, 0, -3, -3, -4, -4;
  const std::vector<QuadFace> master{{0, 1, 2, 3}};
  const std::vector<QuadFace> slave{{4, 5, 6, 7}};
  NodeToSurfaceContact contact(nodes, slave, master, settings_with(1000.0, 1, 0.1, 10.0));
  const Eigen::VectorXd force = contact_force_at(contact, Eigen::VectorXd::Zero(24));
  EXPECT_EQ(contact.statistics().nodes_in_contact, 0);
  EXPECT_EQ(force.norm(), 0.0);
}

TEST(NodeToSurfaceContact, ANodeUnderTheBearingFaceIsNotTakenBySideFaceAtItsEdge) {
  // The master body's top face z = 0 (x in [0, 10], y in [0, 4], normal +z) and a side face
  // y = 4 (x in [0, 20], z in [-1, 0], normal +y) whose edge lies in the top face's plane. A
  // slave nodes 1e-8 mm beyond the top face's edge x = 10 (a round-off: not 'inside' it) and
  // 0.001 mm under its plane also lies 'inside' the side face at its edge, 2 mm behind it, over
  // half the side face's smaller half-size (0.5 mm) deep (the
  // Girona D3 half model stopped on this: a mortar node on the core's corner). Theory: those two
  // bear on the top face, N = k_N 0.001 along -z on each; the slave nodes 1 mm beyond the top
  // face are beside the body's convex edge: open.
  Eigen::Matrix3Xd nodes(3, 12);
  nodes << 0, 10, 10, 0, 0, 20, 20, 0, 10 + 1e-8, 11, 11, 10 + 1e-8, //
      0, 0, 4, 4, 4, 4, 4, 4, 2, 2, 3, 3,                            //
      0, 0, 0, 0, 0, 0, -1, -1, -0.001, -0.001, -0.001, -0.001;
  const std::vector<QuadFace> master{{0, 1, 2, 3}, {4, 5, 6, 7}};
  const std::vector<QuadFace> slave{{8, 9, 10, 11}};
  NodeToSurfaceContact contact(nodes, slave, master, settings_with(1000.0, 1, 0.1, 10.0));
  const Eigen::VectorXd force = contact_force_at(contact, Eigen::VectorXd::Zero(36));
  EXPECT_EQ(contact.statistics().nodes_in_contact, 2);
  const double k_N = 1000.0 * 0.25 * (1.0 - 1e-8); // a quarter of the slave face's area
  for (int node : {8, 11}) {
    EXPECT_NEAR(node_force(force, node).z(), -k_N * 0.001, 1e-12) << node;
    EXPECT_NEAR(node_force(force, node).y(), 0.0, 1e-12) << node;
  }
  for (int node : {9, 10})
    EXPECT_EQ(node_force(force, node).norm(), 0.0) << node;
}

TEST(NodeToSurfaceContact, RigidRotationOfEverythingRotatesTheForces) {
  // Objectivity: the same history (press, slide along a diagonal into slip, back into stick)
  // on the warped pair and on the pair rotated by R: forces R f, same energies.
  const auto lift = [](int i, int j) { return 0.2 * std::cos(0.9 * i - 0.4 * j); };
  const Pair pair(2, 2, 5.0, {3.0, 3.5}, 2.0, 0.3, lift);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -0.8, 0.5).normalized()).toRotationMatrix();
  const Eigen::Matrix3Xd rotated_nodes = R * pair.nodes;
  const NodeToSurfaceContactSettings settings = settings_with(700.0, 1.5, 0.2);
  NodeToSurfaceContact original(pair.nodes, pair.slave, pair.master, settings);
  NodeToSurfaceContact rotated(rotated_nodes, pair.slave, pair.master, settings);
  const std::vector<Eigen::Vector3d> history = {{0, 0, -0.4},
                                                {0.01, 0.004, -0.42},
                                                {0.05, 0.03, -0.42},
                                                {0.2, 0.1, -0.45},
                                                {0.19, 0.1, -0.45}};
  int slipping_steps = 0;
  for (const Eigen::Vector3d& shift : history) {
    const Eigen::VectorXd u = pair.slave_moved(shift);
    Eigen::VectorXd u_rotated = u;
    for (int n = 0; n < pair.nodes.cols(); ++n)
      u_rotated.segment<3>(3 * n) = R * u.segment<3>(3 * n);
    const Eigen::VectorXd f = contact_force_at(original, u);
    const Eigen::VectorXd f_rotated = contact_force_at(rotated, u_rotated);
    EXPECT_EQ(original.statistics().nodes_in_contact, 4);
    slipping_steps += original.statistics().nodes_slipping > 0 ? 1 : 0;
    EXPECT_EQ(original.statistics().nodes_slipping, rotated.statistics().nodes_slipping);
    const double scale = f.cwiseAbs().maxCoeff();
    for (int n = 0; n < pair.nodes.cols(); ++n)
      EXPECT_LT((R * node_force(f, n) - node_force(f_rotated, n)).norm(), 1e-10 * scale);
    original.commit();
    rotated.commit();
    EXPECT_NEAR(original.stored_energy(), rotated.stored_energy(),
                1e-10 * original.stored_energy());
    EXPECT_NEAR(original.dissipated_energy(), rotated.dissipated_energy(),
                1e-10 * (1.0 + original.dissipated_energy()));
  }
  EXPECT_GT(slipping_steps, 0);
  EXPECT_GT(original.dissipated_energy(), 0.0);
}

TEST(NodeToSurfaceContact, SearchProjectsOnlyNearFacesAndFollowsALongSlide) {
  // A strip of 100 master faces 10 mm long (x in [0, 1000]): a slave face 50 mm above it
  // costs no projection at all; pressed into it at x = 500, each node is projected on the
  // faces within the search distance only (at most the 2 faces that meet at a node's
  // station, here x = 500 or 502 mm: 3 faces for the face's 4 nodes), out of the few listed in
  // its bucket. Then the master slides 300 mm under the slave in 1 mm steps: the buckets are
  // rebuilt after each half bucket (5 mm) of sliding, not every step, and the contact is
  // never lost.
  const Pair pair(100, 1, 10.0, {500.0, 4.0}, 2.0, 50.0);
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings_with(1000, 1, 0.1));
  contact_force_at(contact, pair.slave_moved({0, 0, 0}));
  EXPECT_EQ(contact.statistics().projections_last_call, 0);
  EXPECT_EQ(contact.statistics().nodes_in_contact, 0);

  Eigen::VectorXd u = pair.slave_moved({0, 0, -50.01});
  contact_force_at(contact, u);
  EXPECT_EQ(contact.statistics().nodes_in_contact, 4);
  EXPECT_LE(contact.statistics().projections_last_call, 4 * 2);
  EXPECT_LE(contact.statistics().box_tests_last_call, 4 * 4); // 100 faces, 4 per bucket
  contact.commit();
  const long builds_before = contact.statistics().bucket_builds;
  EXPECT_EQ(builds_before, 1);
  for (int step = 1; step <= 300; ++step) {
    for (int n = 0; n < pair.master_node_count; ++n)
      u[3 * n] = -1.0 * step;
    contact_force_at(contact, u);
    ASSERT_EQ(contact.statistics().nodes_in_contact, 4) << "step " << step;
    // a node on a face edge: 2 faces, and as many for its moved anchor (slipping)
    EXPECT_LE(contact.statistics().projections_last_call, 4 * (2 + 2));
    contact.commit();
  }
  // rebuilt when a master node has moved more than 5 mm: every 6th step
  const long builds = contact.statistics().bucket_builds - builds_before;
  EXPECT_EQ(builds, 300 / 6);
}

TEST(NodeToSurfaceContact, TwoPassOnMatchingMeshesIsAsStiffAsOnePass) {
  // Two facing 2 x 2 grids with coincident nodes in plan: in two-pass mode each surface is
  // the other's master with half the penalty, so the same penetration gives the same total
  // force as one pass (every node of either side finds the other side at the same gap).
  const double penalty = 300.0, press = 0.05;
  Eigen::Matrix3Xd nodes(3, 18);
  std::vector<QuadFace> lower, upper;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) {
      nodes.col(i + 3 * j) = Eigen::Vector3d(5.0 * i, 5.0 * j, 0.0);
      nodes.col(9 + i + 3 * j) = Eigen::Vector3d(5.0 * i, 5.0 * j, 0.0);
    }
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = i + 3 * j;
      lower.push_back({a, a + 1, a + 4, a + 3});                 // outward +z
      upper.push_back({9 + a, 9 + a + 3, 9 + a + 4, 9 + a + 1}); // outward -z
    }
  Eigen::VectorXd u = Eigen::VectorXd::Zero(54);
  for (int n = 9; n < 18; ++n)
    u[3 * n + 2] = -press;
  NodeToSurfaceContactSettings one = settings_with(penalty, 1.0, 0.1);
  NodeToSurfaceContactSettings two = one;
  two.two_pass = true;
  NodeToSurfaceContact single(nodes, upper, lower, one);
  NodeToSurfaceContact twice(nodes, upper, lower, two);
  ASSERT_EQ(twice.pass_count(), 2);
  const Eigen::VectorXd f1 = contact_force_at(single, u);
  const Eigen::VectorXd f2 = contact_force_at(twice, u);
  double upper_total_1 = 0.0, upper_total_2 = 0.0;
  for (int n = 9; n < 18; ++n) {
    upper_total_1 += f1[3 * n + 2];
    upper_total_2 += f2[3 * n + 2];
  }
  // theory: penalty x area x penetration, the grid's area 10 x 10 mm^2
  EXPECT_NEAR(upper_total_1, -penalty * 100.0 * press, 1e-9);
  EXPECT_NEAR(upper_total_2, -penalty * 100.0 * press, 1e-9);
  EXPECT_EQ(twice.statistics().nodes_in_contact, 18);
}

TEST(NodeToSurfaceContact, ResultsDoNotDependOnTheThreadCount) {
  // Two-pass contact of a slave face on a warped 4 x 4 grid (4 + 25 slave nodes), pressed and
  // slid into slip: forces, states and energies bitwise equal for 1, 2, 3 and 5 threads (each
  // node writes its own record, summed in node order).
  const auto lift = [](int i, int j) { return 0.1 * std::sin(0.8 * i + 0.5 * j); };
  const Pair pair(4, 4, 2.0, {2.5, 3.0}, 3.0, 0.3, lift);
  NodeToSurfaceContactSettings settings = settings_with(600.0, 1.0, 0.2);
  settings.two_pass = true;
  const std::vector<Eigen::Vector3d> history = {
      {0, 0, -0.45}, {0.3, 0.1, -0.47}, {0.6, 0.2, -0.47}};
  std::vector<Eigen::VectorXd> reference_forces;
  double reference_dissipation = 0.0;
  for (int threads : {1, 2, 3, 5}) {
    NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings);
    contact.set_threads(threads);
    std::vector<Eigen::VectorXd> forces;
    for (const Eigen::Vector3d& shift : history) {
      forces.push_back(contact_force_at(contact, pair.slave_moved(shift)));
      contact.commit();
    }
    if (threads == 1) {
      reference_forces = forces;
      reference_dissipation = contact.dissipated_energy();
      EXPECT_GT(contact.statistics().nodes_in_contact, 4);
      EXPECT_GT(contact.statistics().nodes_slipping, 0);
      continue;
    }
    for (std::size_t k = 0; k < forces.size(); ++k)
      EXPECT_TRUE(forces[k] == reference_forces[k]) << threads << " threads, step " << k;
    EXPECT_EQ(contact.dissipated_energy(), reference_dissipation);
  }
  Eigen::Matrix3Xd nodes = pair.nodes;
  NodeToSurfaceContact contact(nodes, pair.slave, pair.master, settings);
  EXPECT_THROW(contact.set_threads(0), std::invalid_argument);
}

TEST(NodeToSurfaceContact, FrequencyBoundIsTheStiffestSpringOnTheLightestMasses) {
  // k (1/m_s + 1/m_master) with k = max(k_N, k_T), at the worst node (solid_interaction.hpp)
  const Pair pair(1, 1, 10.0, {4.0, 4.0}, 2.0, 0.0);
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings_with(1000, 2.5, 0.1));
  Eigen::VectorXd mass = Eigen::VectorXd::Constant(pair.dof_count(), 1e-6);
  mass.segment<3>(3 * pair.slave_nodes[2]).setConstant(2e-7); // lightest slave
  mass.segment<3>(3 * 1).setConstant(4e-7);                   // lightest master
  const double k_T = 2.5 * 1000.0 * 1.0;
  EXPECT_DOUBLE_EQ(contact.frequency_bound_squared(mass), k_T * (1.0 / 2e-7 + 1.0 / 4e-7));
}

TEST(NodeToSurfaceContact, BadSettingsAndFacesAreRefusedNamingTheField) {
  const Pair pair(1, 1, 10.0, {4.0, 4.0}, 2.0, 0.0);
  const auto field_of = [&](NodeToSurfaceContactSettings settings) -> std::string {
    try {
      NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master, settings);
    } catch (const ParameterError& error) {
      EXPECT_NE(std::string(error.what()).find(error.field()), std::string::npos);
      return error.field();
    }
    return "accepted";
  };
  const NodeToSurfaceContactSettings good = settings_with(1000, 1, 0.1);
  EXPECT_EQ(field_of(good), "accepted");
  NodeToSurfaceContactSettings bad = good;
  bad.normal_penalty = 0.0;
  EXPECT_EQ(field_of(bad), "normal_penalty");
  bad = good;
  bad.tangential_stiffness_ratio = -1.0;
  EXPECT_EQ(field_of(bad), "tangential_stiffness_ratio");
  bad = good;
  bad.friction_coefficient = std::nan("");
  EXPECT_EQ(field_of(bad), "friction_coefficient");
  bad = good;
  bad.search_distance = 0.0;
  EXPECT_EQ(field_of(bad), "search_distance");

  const auto message_of = [&](std::vector<QuadFace> slave, std::vector<QuadFace> master) {
    try {
      NodeToSurfaceContact contact(pair.nodes, slave, master, good);
    } catch (const std::invalid_argument& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message_of(pair.slave, {{0, 1, 2, 99}}).find("master_surface[0]: node 99"),
            std::string::npos);
  EXPECT_NE(message_of({{4, 5, 5, 7}}, pair.master).find("slave_surface[0]: node 5 appears twice"),
            std::string::npos);
  EXPECT_NE(message_of(pair.slave, {}).find("master_surface has no face"), std::string::npos);
}

TEST(NodeToSurfaceContact, APenetrationDeeperThanHalfTheSearchDistanceIsRefused) {
  const Pair pair(1, 1, 10.0, {4.0, 4.0}, 2.0, 0.0);
  NodeToSurfaceContact contact(pair.nodes, pair.slave, pair.master,
                               settings_with(1000, 1, 0.1, 0.2));
  Eigen::VectorXd force = Eigen::VectorXd::Zero(pair.dof_count());
  std::string reason;
  EXPECT_TRUE(contact.add_force(pair.slave_moved({0, 0, -0.09}), force, reason)) << reason;
  EXPECT_FALSE(contact.add_force(pair.slave_moved({0, 0, -0.11}), force, reason));
  EXPECT_NE(reason.find("more than half the search distance"), std::string::npos) << reason;
}

} // namespace
} // namespace brb::solid
