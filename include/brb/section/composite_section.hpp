// CompositeSection: two sections acting at the same point of a member and deforming
// together (plane sections shared), e.g. a BRB casing: the steel tube's fibers with the
// steel law plus the mortar fill's fibers with MortarUniaxial (DESIGN.md section 4). The
// resultants, tangents, torsional stiffnesses and energies are the sums of the parts'.
// Same interface as FiberSection (evaluate, commit, revert_to_committed, energies).
#pragma once

#include "brb/section/fiber_section.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace brb::section {

template <class SectionA, class SectionB> class CompositeSection {
public:
  using Response = SectionResponse;

  CompositeSection(SectionA first, SectionB second)
      : first_(std::move(first)), second_(std::move(second)) {}

  /// Trial response at a section deformation (e0, kappa_y, kappa_z) shared by both parts.
  const Response& evaluate(const SectionVector& deformation) {
    first_.evaluate(deformation);
    second_.evaluate(deformation);
    return sum_parts();
  }

  void commit() {
    first_.commit();
    second_.commit();
  }
  /// Checkpoints (io/state_archive.hpp).
  template <class Archive, class Self>
  requires io::state_of<Self, CompositeSection>
  friend void state_fields(Archive& archive, Self& section) {
    archive(section.first_, section.second_, section.response_);
  }
  void revert_to_committed() {
    first_.revert_to_committed();
    second_.revert_to_committed();
  }
  /// Splits both parts along their mid-planes (FiberSection::split_halves; each part's halves
  /// about their own centroids, which for one material is its stiffness centroid). Between
  /// commits only.
  void split_halves(const std::array<double, 2>& fractions) {
    first_.split_halves(fractions);
    second_.split_halves(fractions);
    sum_parts();
  }
  /// Split fractions (phi_y, phi_z) of the committed state (the second part's: the fill).
  const std::array<double, 2>& split_fractions() const { return second_.split_fractions(); }

  /// G J of the parts in parallel (N mm^2).
  double torsional_stiffness() const {
    return first_.torsional_stiffness() + second_.torsional_stiffness();
  }
  /// Free energy of the trial state per unit length (N mm / mm).
  double stored_energy() const { return first_.stored_energy() + second_.stored_energy(); }
  /// Energy dissipated per unit length (N mm / mm), trial state.
  double dissipated_energy() const {
    return first_.dissipated_energy() + second_.dissipated_energy();
  }
  /// The parts' trapezoidal stress work per unit length (FiberSection::stress_work).
  double stress_work() const { return first_.stress_work() + second_.stress_work(); }
  /// Largest damage of either part (trial state).
  double max_damage() const { return std::max(first_.max_damage(), second_.max_damage()); }

  const SectionA& first() const { return first_; }
  const SectionB& second() const { return second_; }
  const Response& last_response() const { return response_; }

private:
  /// The parts in parallel: the sum of their last responses, kept as this section's.
  const Response& sum_parts() {
    response_.force = first_.last_response().force + second_.last_response().force;
    response_.tangent = first_.last_response().tangent + second_.last_response().tangent;
    return response_;
  }

  SectionA first_;
  SectionB second_;
  Response response_;
};

} // namespace brb::section
