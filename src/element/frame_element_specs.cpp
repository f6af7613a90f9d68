#include "brb/element/frame_element_specs.hpp"

#include "brb/material/parameter_error.hpp"

#include <cmath>

namespace brb::element {
namespace {

double member_length(const Vector3& position_i, const Vector3& position_j) {
  const double length = (position_j - position_i).norm();
  if (!(length > 0.0) || !std::isfinite(length))
    throw ParameterError("nodes", "the element's two nodes must not coincide (zero length)");
  return length;
}

} // namespace

Vector3 default_orientation(const Vector3& position_i, const Vector3& position_j) {
  const Vector3 axis = (position_j - position_i).normalized();
  const bool along_z = axis.cross(Vector3::UnitZ()).norm() < 1e-6;
  return along_z ? Vector3::UnitX() : Vector3::UnitZ();
}

std::unique_ptr<ElasticBeamColumn> make_elastic_beam_column(const ElasticBeamColumnSpec& spec,
                                                            const Vector3& position_i,
                                                            const Vector3& position_j) {
  spec.section.validate();
  member_length(position_i, position_j); // before default_orientation normalises the chord
  const Vector3 orientation =
      spec.orientation.value_or(default_orientation(position_i, position_j));
  return std::make_unique<ElasticBeamColumn>(spec.nodes, position_i, position_j, spec.section,
                                             orientation, spec.geometry);
}

std::unique_ptr<Truss> make_truss(const TrussSpec& spec, const Vector3& position_i,
                                  const Vector3& position_j) {
  if (!(spec.area > 0.0) || !std::isfinite(spec.area))
    throw ParameterError("area", "the truss's area must be > 0 mm^2");
  const double length = member_length(position_i, position_j);
  return std::make_unique<Truss>(spec.nodes, position_i, position_j, spec.area,
                                 make_uniaxial_law(spec.material, length));
}

std::unique_ptr<UniaxialSpring> make_uniaxial_spring(const UniaxialSpringSpec& spec,
                                                     const Vector3& position_i,
                                                     const Vector3& position_j) {
  static constexpr std::array<const char*, 6> kDofNames{"ux", "uy", "uz", "rx", "ry", "rz"};
  SpringDofLaws laws;
  for (std::size_t dof = 0; dof < laws.size(); ++dof) {
    if (!spec.dofs[dof])
      continue;
    const SpringDofSpec& dof_spec = *spec.dofs[dof];
    const std::string field = std::string("dofs.") + kDofNames[dof];
    if (!(dof_spec.force_scale > 0.0) || !std::isfinite(dof_spec.force_scale))
      throw ParameterError(field, "the force scale of a spring law must be > 0");
    if (!(dof_spec.deformation_scale > 0.0) || !std::isfinite(dof_spec.deformation_scale))
      throw ParameterError(field, "the deformation scale of a spring law must be > 0");
    laws[dof] = SpringDofLaw{make_uniaxial_law(dof_spec.material, dof_spec.deformation_scale),
                             dof_spec.force_scale, dof_spec.deformation_scale};
  }
  return std::make_unique<UniaxialSpring>(spec.nodes, position_i, position_j, std::move(laws),
                                          spec.axes);
}

} // namespace brb::element
