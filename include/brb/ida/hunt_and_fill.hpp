// The hunt-and-fill tracing of one record's IDA curve (Vamvatsikos & Cornell 2002,
// "Incremental dynamic analysis", Earthq. Eng. Struct. Dyn. 31(3), sec. 5; and 2004,
// "Applied incremental dynamic analysis", Earthq. Spectra 20(2), "hunt & fill"):
//   1. hunt up: intensities first, first + step, ... with the step growing by `step_growth`
//      after every non-collapsing run (IM_k+1 = IM_k + step + k * step_growth), until a run
//      collapses (or the budget is spent, or `max_intensity` is reached: a hunting intensity
//      above it is replaced by `max_intensity` itself, and hunting ends once that run
//      survived);
//   2. bracket: bisection between the highest non-collapsing intensity below the lowest
//      collapsing one (0 when there is none) and that collapsing one, until the bracket is no
//      wider than `resolution`. When the first run collapses, the lower end is 0, so the
//      intensity is halved until a run survives; if every run down to `resolution` collapses,
//      the trace ends with no survival (capacity below `resolution`);
//   3. fill: the remaining budget goes to the midpoints of the largest gaps between
//      successive non-collapsing intensities below the lowest collapse (the curve below the
//      flatline; the origin is not one of them), largest first; gaps within 1e-9 relative of
//      each other count as equal and the lowest goes first. Only gaps wider than `resolution`
//      are filled: when none is left the trace is complete.
// Non-monotonic curves: a fill run that collapses (a collapse window below the bracket found)
// becomes the lowest collapse, and the bracket between it and the highest survival below it
// is bisected before filling resumes. Survivals above the lowest collapse ("resurrection")
// are kept in runs() but do not count: the bracket is always the lowest collapse and the
// highest survival below it.
// The tracer is a pure state machine: it asks for intensities and is told whether each run
// collapsed. The next intensity is a function of the settings and the answers alone (no other
// state, sums in a fixed order), so a run replayed from a journal asks for bitwise the same
// intensities (deterministic, resumable, independent of threads). It never asks an intensity
// twice.
#pragma once

#include <optional>
#include <vector>

namespace brb::ida {

struct HuntFillSettings {
  double first_intensity = 0.1; ///< IM of the first run (> 0), e.g. g for Sa
  double step = 0.1;            ///< first hunting step (> 0)
  double step_growth = 0.05;    ///< added to the step after each hunting run (>= 0)
  double resolution = 0.02;     ///< bracket width at which bisection stops (> 0)
  int max_runs = 12;            ///< run budget per record (>= 1)
  double max_intensity = 0.0;   ///< hunting stops above it (0: no limit)
};

/// One run the tracer asked for and what it gave.
struct TracedRun {
  double intensity = 0.0;
  bool collapsed = false;
};

class HuntAndFill {
public:
  /// Throws std::invalid_argument for settings outside their ranges (the message names the
  /// field); every value must be finite, and max_intensity must be 0 or >= first_intensity.
  explicit HuntAndFill(const HuntFillSettings& settings);

  /// The intensity of the next run; nothing when the trace is complete (budget spent, or
  /// the collapse bracket resolved and no gap is left worth filling).
  std::optional<double> next_intensity() const;

  /// The outcome of the run at `intensity`, which must be the value next_intensity() gave
  /// (std::logic_error otherwise, compared bitwise, and when the trace is complete).
  void record(double intensity, bool collapsed);

  /// The runs in the order they were made.
  const std::vector<TracedRun>& runs() const { return runs_; }

  /// The lowest collapsing intensity so far (nothing when no run collapsed).
  std::optional<double> lowest_collapse() const;
  /// The highest non-collapsing intensity below the lowest collapse (or the highest of all
  /// when nothing collapsed); nothing when every run collapsed.
  std::optional<double> highest_survival() const;

private:
  HuntFillSettings settings_;
  std::vector<TracedRun> runs_;
  std::optional<double> next_;
  void plan_next();
};

} // namespace brb::ida
