// The qualification loading sequence of a brace test, ANSI/AISC 341-16 K3.4c
// (AISC341_NOTES.md): deformations are the brace's axial deformation (mm),
//   1. 2 cycles at Delta_by          2. 2 cycles at 0.5 Delta_bm
//   3. 2 cycles at 1.0 Delta_bm      4. 2 cycles at 1.5 Delta_bm
//   5. 2 cycles at 2.0 Delta_bm
//   6. further complete cycles at 1.5 Delta_bm until the cumulative inelastic axial
//      deformation is at least 200 Delta_by.
// The virtual test adds the cycles of step 6 one by one while the brace's own cumulative
// inelastic deformation (computed from its response) is short of the target
// (qualification.hpp); the estimate below says beforehand how many that should take.
#pragma once

#include "brb/design/edition.hpp"
#include "brb/io/protocol.hpp"

#include <vector>

namespace brb::design {

struct QualificationSequence {
  double yield_deformation = 0.0;  ///< Delta_by, mm
  double design_deformation = 0.0; ///< Delta_bm, mm
  /// Steps 1 to 5 (mm), in order.
  std::vector<io::CycleGroup> groups;
  double extra_amplitude = 0.0;   ///< step 6: 1.5 Delta_bm, mm
  double cumulative_target = 0.0; ///< step 6: the target, multiples of Delta_by (200)
};

/// The sequence for Delta_by and Delta_bm (mm, both > 0; std::invalid_argument otherwise).
QualificationSequence qualification_sequence(double yield_deformation, double design_deformation,
                                             const EditionParameters& edition);

/// Cumulative inelastic deformation (multiples of Delta_by) of one full cycle of amplitude A
/// (0 -> +A -> -A -> 0) of an elastic-perfectly plastic brace of yield deformation Delta_by
/// in its stabilised loop: each half cycle yields over 2 (A - Delta_by), so a cycle adds
/// 4 max(0, A - Delta_by) / Delta_by (rigid-plastic beyond the elastic range). The usual hand
/// count of the K3.4c sequence (e.g. a cycle at 2 Delta_by adds 4).
double estimated_cycle_inelastic_deformation(double amplitude, double yield_deformation);

/// The estimate over steps 1 to 5 (multiples of Delta_by).
double estimated_inelastic_deformation_before_extra(const QualificationSequence& sequence);

/// Number of step-6 cycles the elastic-perfectly plastic estimate needs to reach the target:
/// ceil((target - estimate of steps 1-5) / estimate of one 1.5 Delta_bm cycle), 0 when steps
/// 1-5 reach it. Throws std::invalid_argument when 1.5 Delta_bm <= Delta_by (step 6 would
/// never add inelastic deformation).
int estimated_extra_cycles(const QualificationSequence& sequence);

/// Steps 1 to 5 followed by `extra_cycles` cycles at 1.5 Delta_bm, as cycle groups (mm).
std::vector<io::CycleGroup> sequence_groups(const QualificationSequence& sequence,
                                            int extra_cycles);

} // namespace brb::design
