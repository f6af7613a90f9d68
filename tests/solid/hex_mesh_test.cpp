// Structured prism mesh: numbering, node sets, distortion (reference values: the
// numbering contract of hex_mesh.hpp and the box's exact volume).
#include "brb/solid/hex8.hpp"
#include "brb/solid/hex_mesh.hpp"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace brb::solid {
namespace {

NodeMatrix element_coordinates(const HexMesh& mesh, int e) {
  NodeMatrix x;
  for (int a = 0; a < 8; ++a)
    x.col(a) = mesh.nodes.col(mesh.elements[e][a]);
  return x;
}

TEST(PrismMesh, CountsAndNumberingFollowTheDocumentedOrder) {
  const StructuredPrismMesh prism(Eigen::Vector3d(30.0, 20.0, 40.0), {3, 2, 4});
  const HexMesh& mesh = prism.mesh();
  ASSERT_EQ(mesh.node_count(), 4 * 3 * 5);
  ASSERT_EQ(mesh.element_count(), 3 * 2 * 4);
  // node (i, j, k) = i + 4 (j + 3 k), at (10 i, 10 j, 10 k)
  EXPECT_EQ(prism.node_index(2, 1, 3), 2 + 4 * (1 + 3 * 3));
  EXPECT_TRUE(mesh.nodes.col(prism.node_index(2, 1, 3)).isApprox(Eigen::Vector3d(20, 10, 30)));
  // element (1, 1, 2) = 1 + 3 (1 + 2 * 2); its first node is (1, 1, 2), its seventh (2, 2, 3)
  const HexConnectivity& element = mesh.elements[prism.element_index(1, 1, 2)];
  EXPECT_EQ(prism.element_index(1, 1, 2), 1 + 3 * (1 + 2 * 2));
  EXPECT_EQ(element[0], prism.node_index(1, 1, 2));
  EXPECT_EQ(element[1], prism.node_index(2, 1, 2));
  EXPECT_EQ(element[3], prism.node_index(1, 2, 2));
  EXPECT_EQ(element[6], prism.node_index(2, 2, 3));
  // every element is a 10 x 10 x 10 cube with a positive Jacobian
  for (int e = 0; e < mesh.element_count(); ++e)
    EXPECT_NEAR(hex8_reference(element_coordinates(mesh, e)).volume, 1000.0, 1e-9);
}

TEST(PrismMesh, FacesHoldExactlyTheNodesOnThem) {
  const StructuredPrismMesh prism(Eigen::Vector3d(30.0, 20.0, 40.0), {3, 2, 4});
  const HexMesh& mesh = prism.mesh();
  const struct {
    PrismFace face;
    int axis;
    double coordinate;
    std::size_t count;
  } cases[] = {{PrismFace::x_min, 0, 0.0, 15}, {PrismFace::x_max, 0, 30.0, 15},
               {PrismFace::y_min, 1, 0.0, 20}, {PrismFace::y_max, 1, 20.0, 20},
               {PrismFace::z_min, 2, 0.0, 12}, {PrismFace::z_max, 2, 40.0, 12}};
  for (const auto& c : cases) {
    const std::vector<int> nodes = prism.face_nodes(c.face);
    EXPECT_EQ(nodes.size(), c.count);
    EXPECT_TRUE(std::is_sorted(nodes.begin(), nodes.end()));
    const std::set<int> on_face(nodes.begin(), nodes.end());
    for (int n = 0; n < mesh.node_count(); ++n)
      EXPECT_EQ(on_face.count(n) == 1, mesh.nodes(c.axis, n) == c.coordinate) << "node " << n;
  }
  int interior = 0;
  for (int n = 0; n < mesh.node_count(); ++n)
    interior += prism.is_interior(n) ? 1 : 0;
  EXPECT_EQ(interior, 2 * 1 * 3);
}

TEST(PrismMesh, DistortionMovesOnlyInteriorNodesAndKeepsTheVolume) {
  StructuredPrismMesh prism(Eigen::Vector3d(10.0, 12.0, 14.0), {4, 4, 4});
  const Eigen::Matrix3Xd original = prism.mesh().nodes;
  prism.distort_interior_nodes(0.3, 7);
  const HexMesh& mesh = prism.mesh();
  int moved = 0;
  for (int n = 0; n < mesh.node_count(); ++n) {
    const bool same = (mesh.nodes.col(n) - original.col(n)).norm() == 0.0;
    EXPECT_EQ(same, !prism.is_interior(n)) << "node " << n;
    moved += same ? 0 : 1;
  }
  EXPECT_EQ(moved, 27);
  // the trilinear elements still tile the box: their volumes add up to it exactly
  double volume = 0.0;
  for (int e = 0; e < mesh.element_count(); ++e)
    volume += hex8_reference(element_coordinates(mesh, e)).volume;
  EXPECT_NEAR(volume, 10.0 * 12.0 * 14.0, 1e-10 * 1680.0);
}

TEST(PrismMesh, RejectsBadInput) {
  EXPECT_THROW(StructuredPrismMesh(Eigen::Vector3d(0.0, 1.0, 1.0), {1, 1, 1}),
               std::invalid_argument);
  EXPECT_THROW(StructuredPrismMesh(Eigen::Vector3d(1.0, 1.0, 1.0), {1, 0, 1}),
               std::invalid_argument);
  StructuredPrismMesh prism(Eigen::Vector3d(1.0, 1.0, 1.0), {2, 2, 2});
  EXPECT_THROW(prism.distort_interior_nodes(0.5, 1), std::invalid_argument);
}

} // namespace
} // namespace brb::solid
