// Comparison of a model's force history with a laboratory record's at the same deformation
// points (issue 4 acceptance): normalised RMS force error, loop energy per cycle and its
// relative error, and beta = |Pmax compression| / Tmax per cycle. Pure functions of the
// three series; units N and mm (energies N mm).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace brb::validation {

/// Normalised RMS force error: sqrt(sum (F_model - F_test)^2) / sqrt(sum F_test^2), the RMS of
/// the difference over the RMS of the test force (a relative L2 error). The RMS of the test
/// force rather than its peak: a peak is set by one point (a spike of the record would set
/// the scale), and a record with many small cycles and one large one would have its
/// small-cycle errors divided by the large cycle's force. The points are the protocol's,
/// about evenly spaced along the deformation path, so the sums weight the history by its
/// deformation travel, not by the laboratory's sampling rate. Throws std::invalid_argument
/// for series of different or zero length, or a test force that is zero everywhere.
double normalised_rms_force_error(std::span<const double> model_force,
                                  std::span<const double> test_force);

/// A cycle: points [first, last] (inclusive) of the deformation history.
struct CycleSpan {
  std::size_t first = 0;
  std::size_t last = 0;
};

/// Full cycles of a deformation history, segmented by its reversals (find_reversals with
/// `reversal_threshold`, mm): the history's leading reversal kind is that of its first
/// reversal (a maximum for a tension-first history); each cycle runs from one reversal of
/// that kind to the next, so it holds one excursion each way (one tension + one compression
/// excursion) and closes a loop. The part before the first reversal (the virgin loading) and
/// after the last reversal of the leading kind (an unfinished cycle) belong to no cycle.
std::vector<CycleSpan> segment_cycles(std::span<const double> deformation,
                                      double reversal_threshold);

/// Loop energy of `cycle`: trapezoidal integral of F d(delta) over its increments (N mm).
double loop_energy(std::span<const double> deformation, std::span<const double> force,
                   CycleSpan cycle);

/// beta of `cycle` = |min F| / max F over its points (compression over tension peak);
/// NaN when the cycle has no positive force.
double compression_tension_ratio(std::span<const double> force, CycleSpan cycle);

/// Peak forces of `cycle` over its points (N, magnitudes): the largest force and the largest
/// compression |min F|; 0 for a direction the cycle does not reach.
struct CyclePeaks {
  double tension = 0.0;
  double compression = 0.0;
};
CyclePeaks cycle_peaks(std::span<const double> force, CycleSpan cycle);

/// Excursions of a deformation history: the spans between consecutive turning points,
/// counting the first and the last point as turning points (find_reversals with
/// `reversal_threshold`, mm). A monotonic or half-cycle protocol (the source's small-BRB cases
/// 1 and 2), which closes no cycle, still has one or two excursions. A span of zero length
/// (a history of one point) is not one.
std::vector<CycleSpan> segment_excursions(std::span<const double> deformation,
                                          double reversal_threshold);

/// Peak force of an excursion in its own direction (N, magnitude): the largest force of an
/// elongating excursion, the largest compression of a shortening one (0 when it has none).
double excursion_peak(std::span<const double> deformation, std::span<const double> force,
                      CycleSpan excursion);

struct RecordComparisonOptions {
  /// mm (>= 0): reversal noise threshold for segment_cycles; the specimens use 0.1 dy.
  double reversal_threshold = 0.0;
  /// Cycles whose test loop energy is below this fraction of the largest test loop energy
  /// are not scored (energy error and beta): nearly elastic cycles, whose loop area is a
  /// small difference of large numbers and is dominated by measurement noise, and whose
  /// beta compares two elastic forces.
  double energy_floor_fraction = 0.05;
  /// N (>= 0): a scored cycle's beta is compared only where the test's tension and
  /// compression peaks both reach this force; the specimens use the core's yield force
  /// Py = fy A_c. A cycle of an irregular record segmented from maximum to maximum can start
  /// at a maximum the test barely loaded in tension (PC500: 0.27 MN against Py = 1.49 MN,
  /// test beta 10.6): its beta divides by an elastic force and says nothing about the
  /// compression overstrength that beta measures (AISC 341 K3: at yield-level cycles).
  double beta_force_floor = 0.0;
};

struct CycleComparison {
  CycleSpan span;
  double test_energy = 0.0;  ///< N mm
  double model_energy = 0.0; ///< N mm
  double test_beta = 0.0;
  double model_beta = 0.0;
  CyclePeaks test_peaks;  ///< N
  CyclePeaks model_peaks; ///< N
  bool scored = false;    ///< test energy at or above the floor
  /// |model - test| / test energy (scored cycles only; 0 otherwise).
  double energy_error() const;
  /// Whether the cycle's beta is compared (compare_with_record): scored, the test has a
  /// tension peak in it (beta = Pmax / Tmax is undefined without one: e.g. a hold point's
  /// wiggle in compression segmented from maximum to maximum) and both its peaks reach the
  /// options' beta_force_floor.
  bool beta_compared = false;
  /// |model - test| beta of a compared cycle (0 otherwise; NaN when the model has no tension
  /// peak where the test has one).
  double beta_difference() const;
  /// |model - test| / test peak force in tension and in compression (scored cycles only; 0
  /// otherwise; infinite when the test cycle has no peak in that direction).
  double peak_tension_error() const;
  double peak_compression_error() const;
};

/// One excursion of the compared points (segment_excursions): its work and its peak force.
struct ExcursionComparison {
  CycleSpan span;
  double test_work = 0.0;  ///< trapezoidal integral of F d(delta) (N mm; loop_energy's rule)
  double model_work = 0.0; ///< N mm
  double test_peak = 0.0;  ///< excursion_peak (N)
  double model_peak = 0.0; ///< N
  bool scored = false;     ///< |test work| at or above the energy floor
  /// |model - test| / |test| work, and the same for the peak (scored excursions only; 0
  /// otherwise; the peak's error is infinite when the test excursion has no peak).
  double work_error() const;
  double peak_error() const;
};

struct RecordComparison {
  double normalised_rms_error = 0.0;
  std::vector<CycleComparison> cycles;
  std::size_t scored_cycles = 0;
  /// Largest relative loop-energy error over the scored cycles (0 without one).
  double max_cycle_energy_error = 0.0;
  /// Largest |beta_model - beta_test| over the beta-compared cycles (0 without one; infinite
  /// when the model has no tension peak in one of them).
  double max_beta_difference = 0.0;
  std::size_t beta_cycles = 0; ///< cycles whose beta is compared (CycleComparison::beta_compared)
  /// Largest relative error of the cycle's peak tension and peak compression over the scored
  /// cycles (0 without one).
  double max_peak_tension_error = 0.0;
  double max_peak_compression_error = 0.0;
  /// AISC 341's adjustment factors from a test (F4.2a, as `brb check` takes them): the
  /// largest beta = Pmax / Tmax over the beta-compared cycles and the largest Tmax (omega =
  /// Tmax / Pysc) over the scored cycles, for the test and for the model at the same points
  /// (0 without such a cycle).
  double largest_test_beta = 0.0;
  double largest_model_beta = 0.0;
  double largest_test_tension = 0.0;  ///< N
  double largest_model_tension = 0.0; ///< N
  /// Excursions (half cycles), scored when |test work| reaches the energy floor's fraction of
  /// the largest |test work| of an excursion: the metrics of a protocol that closes no cycle.
  std::vector<ExcursionComparison> excursions;
  std::size_t scored_excursions = 0;
  double max_excursion_work_error = 0.0; ///< over the scored excursions (0 without one)
  double max_excursion_peak_error = 0.0; ///< over the scored excursions (0 without one)
};

/// The metrics of issue 4 (and the peaks per cycle and per excursion of issue 6) for a model and a
/// test force at the same deformation points (N, mm). Throws std::invalid_argument when the three
/// series differ in length or are empty, or the test force is zero everywhere.
RecordComparison compare_with_record(std::span<const double> deformation,
                                     std::span<const double> test_force,
                                     std::span<const double> model_force,
                                     const RecordComparisonOptions& options);

} // namespace brb::validation
