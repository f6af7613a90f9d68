// Structured hexahedral mesh of a rectangular prism [0, Lx] x [0, Ly] x [0, Lz], the first
// brick of the 3D continuum model (issue 6).
//
// Numbering (documented contract, relied on by the node sets and the tests):
// - node (i, j, k), 0 <= i <= nx, 0 <= j <= ny, 0 <= k <= nz, has index
//   i + (nx + 1) (j + (ny + 1) k): x runs fastest, then y, then z;
// - element (i, j, k), 0 <= i < nx, ..., has index i + nx (j + ny k);
// - an element's 8 nodes follow the usual trilinear order (Hughes, The Finite Element
//   Method, fig. 3.5.2): the face k first, counter-clockwise seen from +z, starting at
//   (i, j), then the face k + 1 in the same order. Natural coordinates (xi, eta, zeta) of
//   node a are the signs in kNaturalCoordinates, so x grows with xi, y with eta, z with zeta.
// Node sets: the six faces x_min, x_max, y_min, y_max, z_min, z_max (sorted node indices).
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace brb::solid {

/// Natural coordinates of the 8 nodes of a trilinear hexahedron (sign of xi, eta, zeta).
inline constexpr std::array<std::array<int, 3>, 8> kNaturalCoordinates{{{-1, -1, -1},
                                                                        {1, -1, -1},
                                                                        {1, 1, -1},
                                                                        {-1, 1, -1},
                                                                        {-1, -1, 1},
                                                                        {1, -1, 1},
                                                                        {1, 1, 1},
                                                                        {-1, 1, 1}}};

using HexConnectivity = std::array<int, 8>;

enum class PrismFace { x_min, x_max, y_min, y_max, z_min, z_max };

struct PrismDivisions {
  int nx = 1;
  int ny = 1;
  int nz = 1;
};

struct HexMesh {
  Eigen::Matrix3Xd nodes; ///< reference coordinates (mm), one column per node
  std::vector<HexConnectivity> elements;

  int node_count() const { return static_cast<int>(nodes.cols()); }
  int element_count() const { return static_cast<int>(elements.size()); }
};

/// A structured mesh of the prism with its numbering kept for the node sets.
class StructuredPrismMesh {
public:
  /// lengths: Lx, Ly, Lz (mm, > 0); divisions >= 1 each. Throws std::invalid_argument.
  StructuredPrismMesh(const Eigen::Vector3d& lengths, PrismDivisions divisions);

  const HexMesh& mesh() const { return mesh_; }
  const PrismDivisions& divisions() const { return divisions_; }
  const Eigen::Vector3d& lengths() const { return lengths_; }

  int node_index(int i, int j, int k) const {
    return i + (divisions_.nx + 1) * (j + (divisions_.ny + 1) * k);
  }
  int element_index(int i, int j, int k) const {
    return i + divisions_.nx * (j + divisions_.ny * k);
  }
  /// The nodes on a face of the prism, sorted.
  std::vector<int> face_nodes(PrismFace face) const;
  /// True when the node lies on no face of the prism.
  bool is_interior(int node) const;

  /// Moves every interior node by a random vector with components uniform in
  /// [-amplitude, amplitude] times the local spacing of its direction (amplitude < 0.5 keeps
  /// every element convex enough for a positive Jacobian). Seeded: reproducible.
  void distort_interior_nodes(double amplitude, std::uint32_t seed);

private:
  Eigen::Vector3d lengths_;
  PrismDivisions divisions_;
  HexMesh mesh_;
};

} // namespace brb::solid
