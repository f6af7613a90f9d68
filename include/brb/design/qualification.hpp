// The virtual qualification test of a brace (ANSI/AISC 341-16 K3, AISC341_NOTES.md): the
// K3.4c sequence run on the full brace model, with the step-6 cycles at 1.5 Delta_bm added
// one at a time until the brace's cumulative inelastic deformation (from its own response,
// BraceIndicators) reaches the target; per cycle Tmax, Pmax, beta, omega and the cumulative
// inelastic deformation; the adjusted strengths (F4.2a) and the acceptance criteria (K3.8).
#pragma once

#include "brb/analysis/cyclic_test.hpp"
#include "brb/design/edition.hpp"
#include "brb/design/loading_sequence.hpp"
#include "brb/model/brace_model.hpp"

#include <optional>
#include <string>
#include <vector>

namespace brb::design {

/// A loading branch "keeps a positive incremental stiffness" when its force never falls
/// behind its running peak (in the direction of loading) by more than this fraction of
/// Pysc. A strict sign test would flag the round-off and the small force steps of the
/// restrained core snapping to a higher buckling mode inside the gap; 1 % of Pysc is far
/// below what a plot shows as a loss of stiffness (project choice, not a code value).
inline constexpr double kStiffnessDropTolerance = 0.01;

struct QualificationInput {
  double design_deformation = 0.0; ///< Delta_bm, mm
  /// Pysc of the tested core (N): Asc times the measured Fysc, or Ry times the specified one;
  /// omega = Tmax / this, and criterion c compares Tmax and Pmax with it.
  double tested_yield_force = 0.0;
  EditionParameters edition;
  double beta_limit = 1.3;
  double max_step = 0.0; ///< mm, largest deformation step (> 0)
  /// Guard on step 6: at most this many times the estimated number of cycles (+ 10).
  int extra_cycle_factor = 3;
  analysis::NewtonSettings settings{};
};

/// One full cycle of the test.
struct QualificationCycle {
  int index = 0;                                 ///< 1-based
  int sequence_step = 0;                         ///< K3.4c step 1 to 6
  double amplitude = 0.0;                        ///< mm
  double max_tension = 0.0;                      ///< Tmax, N (>= 0)
  double max_compression = 0.0;                  ///< Pmax, N, as a magnitude (>= 0)
  double beta = 0.0;                             ///< Pmax / Tmax
  double omega = 0.0;                            ///< Tmax / Pysc of the tested core
  double cumulative_inelastic_deformation = 0.0; ///< multiples of Delta_by, at the cycle's end
  /// Largest fall of the force behind its running peak on a loading branch of the cycle,
  /// as a fraction of Pysc (0: the force never fell while loading).
  double largest_force_drop = 0.0;
  bool beyond_yield = false;        ///< amplitude > Delta_by (criteria c and d apply)
  bool in_adjustment_range = false; ///< amplitude <= 2 Delta_bm (beta and omega)
};

/// One acceptance criterion: `value` compared with `limit` ("<=" or ">=") or a flag.
struct Criterion {
  std::string id;          ///< e.g. "K3.8c tension"
  std::string description; ///< what is checked
  double value = 0.0;
  double limit = 0.0;
  std::string comparison; ///< ">=", "<=", or "flag" (value 0 / 1, must be 0)
  bool passed = false;
  std::string note; ///< where the value comes from
};

struct QualificationResult {
  QualificationSequence sequence;
  int estimated_extra_cycles = 0; ///< elastic-perfectly plastic estimate (loading_sequence.hpp)
  int extra_cycles = 0;           ///< step-6 cycles the brace needed (completed ones)
  bool cumulative_target_reached = false;
  /// The sequence was cut short at the end of the cycle in which the brace failed (core
  /// fracture, global buckling or casing failure), as a laboratory test ends there.
  bool stopped_at_failure = false;
  analysis::CyclicTestResult test; ///< with its element history
  std::vector<QualificationCycle> cycles;
  double beta = 1.0;  ///< design value: largest over the adjustment range, not less than 1.0
  double omega = 0.0; ///< design value: largest over the adjustment range
  /// Mean strain of the yielding core at the 2 Delta_bm peaks (largest magnitude), or none
  /// when the test did not reach them.
  std::optional<double> core_strain_at_2dbm;
  std::vector<Criterion> criteria;
  bool passed = false;
};

/// Runs the test on `brace` (a fresh model: its state is driven from the unloaded state) and
/// judges it. Throws std::invalid_argument for a non-positive Delta_bm, Pysc or max_step.
QualificationResult run_qualification(model::BraceModel& brace, const QualificationInput& input);

/// The failed criteria's ids, joined by ", " (empty when all passed).
std::string failed_criteria(const QualificationResult& result);

} // namespace brb::design
