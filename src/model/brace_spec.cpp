#include "brb/model/brace_spec.hpp"

namespace brb::model {

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

double BraceSpec::total_length() const {
  double length = yielding_length;
  if (transition)
    length += 2.0 * transition->length;
  if (connection)
    length += 2.0 * connection->length;
  return length;
}

} // namespace brb::model
