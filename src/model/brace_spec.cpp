#include "brb/model/brace_spec.hpp"

#include "brb/material/parameter_error.hpp"

#include <cmath>

namespace brb::model {

namespace {

/// The schema's name of `value` in a (name, value) table; "unknown" when it is not listed.
template <class Value, std::size_t N>
std::string_view schema_name(const std::array<std::pair<std::string_view, Value>, N>& names,
                             Value value) {
  for (const auto& [name, listed] : names) {
    if (listed == value)
      return name;
  }
  return "unknown";
}

} // namespace

std::string_view end_faces_name(SolidEndFaces faces) {
  return schema_name(kSolidEndFacesNames, faces);
}

std::string_view hourglass_name(SolidHourglass hourglass) {
  return schema_name(kSolidHourglassNames, hourglass);
}

section::FiberLayout SectionSpec::mesh() const {
  switch (shape) {
  case SectionShape::rectangle:
    return section::mesh_rectangle(width, depth, fibers_a, fibers_b);
  case SectionShape::circle:
    return section::mesh_circle(diameter, fibers_a, fibers_b);
  case SectionShape::cruciform:
    return section::mesh_cruciform(width, depth, thickness, fibers_a, fibers_b);
  case SectionShape::rectangular_tube:
    return section::mesh_rectangular_tube(width, depth, wall, fibers_a, fibers_b);
  case SectionShape::circular_tube:
    return section::mesh_circular_tube(diameter, wall, fibers_a, fibers_b);
  }
  return {};
}

std::pair<double, double> core_extent(const SectionSpec& core) {
  switch (core.shape) {
  case SectionShape::rectangle:
  case SectionShape::cruciform:
  case SectionShape::rectangular_tube:
    return {core.width, core.depth};
  case SectionShape::circle:
  case SectionShape::circular_tube:
    return {core.diameter, core.diameter};
  }
  return {0.0, 0.0};
}

namespace {

/// Inner size of the casing tube along y and z (mm).
std::pair<double, double> tube_inner_size(const SectionSpec& tube) {
  if (tube.shape == SectionShape::circular_tube) {
    const double inner = tube.diameter - 2.0 * tube.wall;
    return {inner, inner};
  }
  if (tube.shape == SectionShape::rectangular_tube)
    return {tube.width - 2.0 * tube.wall, tube.depth - 2.0 * tube.wall};
  throw ParameterError("casing/tube/shape", "must be rectangular_tube or circular_tube");
}

/// Appends a width x depth rectangle centred at (y, z), meshed ny x nz.
void append_block(section::FiberLayout& layout, double y, double z, double width, double depth,
                  int ny, int nz) {
  const section::FiberLayout block = section::mesh_rectangle(width, depth, ny, nz);
  for (std::size_t i = 0; i < block.size(); ++i)
    layout.append(y + block.y[i], z + block.z[i], block.area[i]);
}

} // namespace

std::pair<double, double> CasingSpec::mortar_thickness(const SectionSpec& core) const {
  const auto [inner_y, inner_z] = tube_inner_size(tube);
  const auto [core_y, core_z] = core_extent(core);
  const double thickness_y = 0.5 * (inner_y - core_y) - gap_y;
  const double thickness_z = 0.5 * (inner_z - core_z) - gap_z;
  if (!(thickness_y > 0.0) || !(thickness_z > 0.0)) {
    throw ParameterError("casing/tube", "the core and its gaps must fit inside the tube");
  }
  return {thickness_y, thickness_z};
}

section::FiberLayout CasingSpec::fill_mesh(const SectionSpec& core) const {
  const auto [thickness_y, thickness_z] = mortar_thickness(core);
  const auto [inner_y, inner_z] = tube_inner_size(tube);
  if (tube.shape == SectionShape::circular_tube) {
    if (core.shape != SectionShape::circle)
      throw ParameterError("casing/tube/shape", "a circular tube needs a round (circle) core");
    if (gap_y != gap_z)
      throw ParameterError("casing/gap_z", "must equal gap_y in a circular tube");
    return section::mesh_circular_tube(inner_y, thickness_y, fill_fibers_a, fill_fibers_b);
  }
  // rectangular ring: two full-width slabs normal to z (thickness_z), two side slabs normal
  // to y (thickness_y) between them
  section::FiberLayout layout;
  const double opening_z = inner_z - 2.0 * thickness_z;
  const double slab_z = 0.5 * (inner_z - thickness_z), slab_y = 0.5 * (inner_y - thickness_y);
  append_block(layout, 0.0, slab_z, inner_y, thickness_z, fill_fibers_b, fill_fibers_a);
  append_block(layout, 0.0, -slab_z, inner_y, thickness_z, fill_fibers_b, fill_fibers_a);
  append_block(layout, slab_y, 0.0, thickness_y, opening_z, fill_fibers_a, fill_fibers_b);
  append_block(layout, -slab_y, 0.0, thickness_y, opening_z, fill_fibers_a, fill_fibers_b);
  // Bredt with two wall thicknesses: J = 4 A_m^2 / sum(s / t) on the midline
  const double mid_y = inner_y - thickness_y, mid_z = inner_z - thickness_z;
  layout.torsion_constant =
      4.0 * std::pow(mid_y * mid_z, 2) / (2.0 * mid_y / thickness_z + 2.0 * mid_z / thickness_y);
  return layout;
}

double BraceSpec::total_length() const {
  double length = yielding_length;
  if (transition)
    length += 2.0 * transition->length;
  if (connection)
    length += 2.0 * connection->length;
  return length;
}

} // namespace brb::model
