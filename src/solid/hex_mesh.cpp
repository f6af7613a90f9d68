#include "brb/solid/hex_mesh.hpp"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

namespace brb::solid {

StructuredPrismMesh::StructuredPrismMesh(const Eigen::Vector3d& lengths, PrismDivisions divisions)
    : lengths_(lengths), divisions_(divisions) {
  for (int d = 0; d < 3; ++d) {
    if (!(lengths[d] > 0.0) || !std::isfinite(lengths[d]))
      throw std::invalid_argument("prism mesh: length " + std::to_string(d) +
                                  " must be finite and > 0 mm (got " + std::to_string(lengths[d]) +
                                  ")");
  }
  if (divisions.nx < 1 || divisions.ny < 1 || divisions.nz < 1)
    throw std::invalid_argument("prism mesh: divisions must be >= 1 in every direction (got " +
                                std::to_string(divisions.nx) + ", " + std::to_string(divisions.ny) +
                                ", " + std::to_string(divisions.nz) + ")");
  const int nx = divisions.nx, ny = divisions.ny, nz = divisions.nz;
  mesh_.nodes.resize(3, (nx + 1) * (ny + 1) * (nz + 1));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        mesh_.nodes.col(node_index(i, j, k)) =
            Eigen::Vector3d(lengths[0] * i / nx, lengths[1] * j / ny, lengths[2] * k / nz);
  mesh_.elements.resize(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        HexConnectivity& element = mesh_.elements[element_index(i, j, k)];
        for (int a = 0; a < 8; ++a) {
          const auto& corner = kNaturalCoordinates[a];
          element[a] =
              node_index(i + (corner[0] + 1) / 2, j + (corner[1] + 1) / 2, k + (corner[2] + 1) / 2);
        }
      }
}

std::vector<int> StructuredPrismMesh::face_nodes(PrismFace face) const {
  const int nx = divisions_.nx, ny = divisions_.ny, nz = divisions_.nz;
  std::vector<int> nodes;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) {
        const bool on =
            (face == PrismFace::x_min && i == 0) || (face == PrismFace::x_max && i == nx) ||
            (face == PrismFace::y_min && j == 0) || (face == PrismFace::y_max && j == ny) ||
            (face == PrismFace::z_min && k == 0) || (face == PrismFace::z_max && k == nz);
        if (on)
          nodes.push_back(node_index(i, j, k)); // x fastest: already sorted
      }
  return nodes;
}

bool StructuredPrismMesh::is_interior(int node) const {
  const int nx = divisions_.nx, ny = divisions_.ny, nz = divisions_.nz;
  const int i = node % (nx + 1);
  const int j = (node / (nx + 1)) % (ny + 1);
  const int k = node / ((nx + 1) * (ny + 1));
  return i > 0 && i < nx && j > 0 && j < ny && k > 0 && k < nz;
}

void StructuredPrismMesh::distort_interior_nodes(double amplitude, std::uint32_t seed) {
  if (!(amplitude >= 0.0 && amplitude < 0.5))
    throw std::invalid_argument("prism mesh: distortion amplitude must be in [0, 0.5) (got " +
                                std::to_string(amplitude) + ")");
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-amplitude, amplitude);
  const Eigen::Vector3d spacing(lengths_[0] / divisions_.nx, lengths_[1] / divisions_.ny,
                                lengths_[2] / divisions_.nz);
  for (int node = 0; node < mesh_.node_count(); ++node) {
    if (!is_interior(node))
      continue;
    for (int d = 0; d < 3; ++d)
      mesh_.nodes(d, node) += uniform(generator) * spacing[d];
  }
}

} // namespace brb::solid
