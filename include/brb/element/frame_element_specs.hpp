// Plain parameter structs for the frame elements (what a frame file's reader fills in; no
// JSON here, the io layer maps the fields to JSON paths) and the factories that check them
// and build the elements. Every check throws ParameterError naming the field as the frame
// file writes it: the section keys E, G, A, Iy, Iz, J; "area"; "nodes" (zero length);
// "orientation" (parallel to the member); "dofs"; "axes"; and the material keys of the law
// (E, fy, ..., as in `brb material --params` files).
#pragma once

#include "brb/element/elastic_beam_column.hpp"
#include "brb/element/truss.hpp"
#include "brb/element/uniaxial_law.hpp"
#include "brb/element/uniaxial_spring.hpp"

#include <array>
#include <memory>
#include <optional>

namespace brb::element {

/// The default orientation vector of a member (frame file schema): global Z, or global X
/// for a member along Z (within 1e-6 rad).
Vector3 default_orientation(const Vector3& position_i, const Vector3& position_j);

struct ElasticBeamColumnSpec {
  std::array<int, 2> nodes{};
  ElasticBeamProperties section;
  std::optional<Vector3> orientation; ///< vecxz; default_orientation() when absent
  BeamGeometry geometry = BeamGeometry::linear;
};

struct TrussSpec {
  std::array<int, 2> nodes{};
  double area = 0.0; ///< A (mm^2)
  UniaxialLawParameters material;
};

/// The law of one spring DOF, read as force-deformation through the scales (UniaxialSpring).
struct SpringDofSpec {
  UniaxialLawParameters material;
  double force_scale = 1.0;
  double deformation_scale = 1.0;
};

struct UniaxialSpringSpec {
  std::array<int, 2> nodes{};
  std::array<std::optional<SpringDofSpec>, 6> dofs; ///< ux, uy, uz, rx, ry, rz
  Matrix3 axes = Matrix3::Identity();               ///< columns: the spring's x, y, z
};

/// Checks the spec and builds the element between the nodes' reference positions.
std::unique_ptr<ElasticBeamColumn> make_elastic_beam_column(const ElasticBeamColumnSpec& spec,
                                                            const Vector3& position_i,
                                                            const Vector3& position_j);
/// The law's characteristic length is the truss's length (one material point).
std::unique_ptr<Truss> make_truss(const TrussSpec& spec, const Vector3& position_i,
                                  const Vector3& position_j);
/// The characteristic length of each DOF's law is its deformation scale.
std::unique_ptr<UniaxialSpring> make_uniaxial_spring(const UniaxialSpringSpec& spec,
                                                     const Vector3& position_i,
                                                     const Vector3& position_j);

} // namespace brb::element
