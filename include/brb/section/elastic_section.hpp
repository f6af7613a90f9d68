// ElasticSection: linear elastic resultants (E A, E I_y, E I_z, G J), the same interface
// as FiberSection. For verification problems and elastic members (casing tubes,
// connection zones) where fibers would only cost time.
#pragma once

#include "brb/section/fiber_section.hpp"

namespace brb::section {

struct ElasticSectionProperties {
  double axial_stiffness = 0.0;     ///< E A (N)
  double bending_stiffness_y = 0.0; ///< E I_y (N mm^2)
  double bending_stiffness_z = 0.0; ///< E I_z (N mm^2)
  double torsional_stiffness = 0.0; ///< G J (N mm^2)
};

class ElasticSection {
public:
  using Response = SectionResponse;

  explicit ElasticSection(const ElasticSectionProperties& properties) : properties_(properties) {
    response_.tangent = SectionVector(properties.axial_stiffness, properties.bending_stiffness_y,
                                      properties.bending_stiffness_z)
                            .asDiagonal();
  }

  const Response& evaluate(const SectionVector& deformation) {
    deformation_ = deformation;
    response_.force = response_.tangent * deformation;
    return response_;
  }
  void commit() {}
  void revert_to_committed() {}
  /// Checkpoints (io/state_archive.hpp): the last evaluation, which the energies read.
  template <class Archive, class Self>
  requires io::state_of<Self, ElasticSection>
  friend void state_fields(Archive& archive, Self& section) {
    archive(section.deformation_, section.response_);
  }
  double torsional_stiffness() const { return properties_.torsional_stiffness; }
  double stored_energy() const { return 0.5 * response_.force.dot(deformation_); }
  double dissipated_energy() const { return 0.0; }
  /// A linear section: the trapezoidal stress work is its stored energy exactly.
  double stress_work() const { return stored_energy(); }
  double max_damage() const { return 0.0; }
  const ElasticSectionProperties& properties() const { return properties_; }

private:
  ElasticSectionProperties properties_;
  SectionVector deformation_ = SectionVector::Zero();
  Response response_;
};

} // namespace brb::section
