#include "brb/design/loading_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace brb::design {

QualificationSequence qualification_sequence(double yield_deformation, double design_deformation,
                                             const EditionParameters& edition) {
  if (!(std::isfinite(yield_deformation) && yield_deformation > 0.0))
    throw std::invalid_argument("qualification_sequence: Delta_by must be > 0 mm");
  if (!(std::isfinite(design_deformation) && design_deformation > 0.0))
    throw std::invalid_argument("qualification_sequence: Delta_bm must be > 0 mm");
  QualificationSequence sequence;
  sequence.yield_deformation = yield_deformation;
  sequence.design_deformation = design_deformation;
  // K3.4c steps 1-5 (AISC341_NOTES.md).
  sequence.groups = {{yield_deformation, 2},
                     {0.5 * design_deformation, 2},
                     {1.0 * design_deformation, 2},
                     {1.5 * design_deformation, 2},
                     {2.0 * design_deformation, 2}};
  sequence.extra_amplitude = 1.5 * design_deformation;
  sequence.cumulative_target = edition.cumulative_inelastic_target;
  return sequence;
}

double estimated_cycle_inelastic_deformation(double amplitude, double yield_deformation) {
  return 4.0 * std::max(0.0, amplitude - yield_deformation) / yield_deformation;
}

double estimated_inelastic_deformation_before_extra(const QualificationSequence& sequence) {
  double total = 0.0;
  for (const io::CycleGroup& group : sequence.groups) {
    total += group.cycles *
             estimated_cycle_inelastic_deformation(group.amplitude, sequence.yield_deformation);
  }
  return total;
}

int estimated_extra_cycles(const QualificationSequence& sequence) {
  const double per_cycle =
      estimated_cycle_inelastic_deformation(sequence.extra_amplitude, sequence.yield_deformation);
  const double missing =
      sequence.cumulative_target - estimated_inelastic_deformation_before_extra(sequence);
  if (missing <= 0.0)
    return 0;
  if (per_cycle <= 0.0) {
    throw std::invalid_argument("estimated_extra_cycles: 1.5 Delta_bm does not exceed Delta_by, "
                                "so cycles at 1.5 Delta_bm add no inelastic deformation");
  }
  return static_cast<int>(std::ceil(missing / per_cycle - 1e-12));
}

std::vector<io::CycleGroup> sequence_groups(const QualificationSequence& sequence,
                                            int extra_cycles) {
  std::vector<io::CycleGroup> groups = sequence.groups;
  if (extra_cycles > 0)
    groups.push_back({sequence.extra_amplitude, extra_cycles});
  return groups;
}

} // namespace brb::design
