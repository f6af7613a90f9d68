#include "brb/validation/record_comparison.hpp"

#include "brb/validation/reversals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace brb::validation {

double normalised_rms_force_error(std::span<const double> model_force,
                                  std::span<const double> test_force) {
  if (model_force.size() != test_force.size() || test_force.empty()) {
    throw std::invalid_argument("normalised_rms_force_error: the model and test series must "
                                "have the same, non-zero length");
  }
  double difference = 0.0;
  double reference = 0.0;
  for (std::size_t i = 0; i < test_force.size(); ++i) {
    const double delta = model_force[i] - test_force[i];
    difference += delta * delta;
    reference += test_force[i] * test_force[i];
  }
  if (!(reference > 0.0))
    throw std::invalid_argument("normalised_rms_force_error: the test force is zero everywhere");
  return std::sqrt(difference / reference);
}

std::vector<CycleSpan> segment_cycles(std::span<const double> deformation,
                                      double reversal_threshold) {
  const std::vector<std::size_t> reversals = find_reversals(deformation, reversal_threshold);
  std::vector<CycleSpan> cycles;
  // Reversals alternate maxima and minima, so those of the leading kind are every other one.
  for (std::size_t k = 0; k + 2 < reversals.size(); k += 2)
    cycles.push_back({reversals[k], reversals[k + 2]});
  return cycles;
}

std::vector<CycleSpan> segment_excursions(std::span<const double> deformation,
                                          double reversal_threshold) {
  std::vector<std::size_t> turns{0};
  for (std::size_t reversal : find_reversals(deformation, reversal_threshold))
    turns.push_back(reversal);
  if (!deformation.empty())
    turns.push_back(deformation.size() - 1);
  std::vector<CycleSpan> excursions;
  for (std::size_t k = 0; k + 1 < turns.size(); ++k)
    if (turns[k + 1] > turns[k])
      excursions.push_back({turns[k], turns[k + 1]});
  return excursions;
}

double excursion_peak(std::span<const double> deformation, std::span<const double> force,
                      CycleSpan excursion) {
  const bool elongating = deformation[excursion.last] >= deformation[excursion.first];
  double peak = 0.0;
  for (std::size_t i = excursion.first; i <= excursion.last; ++i)
    peak = std::max(peak, elongating ? force[i] : -force[i]);
  return peak;
}

double loop_energy(std::span<const double> deformation, std::span<const double> force,
                   CycleSpan cycle) {
  double energy = 0.0;
  for (std::size_t i = cycle.first; i < cycle.last; ++i)
    energy += 0.5 * (force[i] + force[i + 1]) * (deformation[i + 1] - deformation[i]);
  return energy;
}

double compression_tension_ratio(std::span<const double> force, CycleSpan cycle) {
  double tension = 0.0;
  double compression = 0.0;
  for (std::size_t i = cycle.first; i <= cycle.last; ++i) {
    tension = std::max(tension, force[i]);
    compression = std::min(compression, force[i]);
  }
  if (!(tension > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  return -compression / tension;
}

CyclePeaks cycle_peaks(std::span<const double> force, CycleSpan cycle) {
  CyclePeaks peaks;
  for (std::size_t i = cycle.first; i <= cycle.last; ++i) {
    peaks.tension = std::max(peaks.tension, force[i]);
    peaks.compression = std::max(peaks.compression, -force[i]);
  }
  return peaks;
}

namespace {

/// |model - test| / test, infinite when the test has no peak (a model peak where the test has
/// none is not a small error).
double relative_peak_error(double model, double test) {
  if (!(test > 0.0))
    return model == test ? 0.0 : std::numeric_limits<double>::infinity();
  return std::abs(model - test) / test;
}

} // namespace

double CycleComparison::peak_tension_error() const {
  return scored ? relative_peak_error(model_peaks.tension, test_peaks.tension) : 0.0;
}

double CycleComparison::peak_compression_error() const {
  return scored ? relative_peak_error(model_peaks.compression, test_peaks.compression) : 0.0;
}

double CycleComparison::energy_error() const {
  return scored ? std::abs(model_energy - test_energy) / test_energy : 0.0;
}

double ExcursionComparison::work_error() const {
  return scored ? std::abs(model_work - test_work) / std::abs(test_work) : 0.0;
}

double ExcursionComparison::peak_error() const {
  return scored ? relative_peak_error(model_peak, test_peak) : 0.0;
}

double CycleComparison::beta_difference() const {
  return beta_compared ? std::abs(model_beta - test_beta) : 0.0;
}

RecordComparison compare_with_record(std::span<const double> deformation,
                                     std::span<const double> test_force,
                                     std::span<const double> model_force,
                                     const RecordComparisonOptions& options) {
  if (deformation.size() != test_force.size() || deformation.size() != model_force.size() ||
      deformation.empty()) {
    throw std::invalid_argument("compare_with_record: deformation, test and model force must "
                                "have the same, non-zero length");
  }
  RecordComparison result;
  result.normalised_rms_error = normalised_rms_force_error(model_force, test_force);

  double largest_test_energy = 0.0;
  for (const CycleSpan& span : segment_cycles(deformation, options.reversal_threshold)) {
    CycleComparison cycle;
    cycle.span = span;
    cycle.test_energy = loop_energy(deformation, test_force, span);
    cycle.model_energy = loop_energy(deformation, model_force, span);
    cycle.test_beta = compression_tension_ratio(test_force, span);
    cycle.model_beta = compression_tension_ratio(model_force, span);
    cycle.test_peaks = cycle_peaks(test_force, span);
    cycle.model_peaks = cycle_peaks(model_force, span);
    largest_test_energy = std::max(largest_test_energy, cycle.test_energy);
    result.cycles.push_back(cycle);
  }
  const double floor = options.energy_floor_fraction * largest_test_energy;
  for (CycleComparison& cycle : result.cycles) {
    cycle.scored = cycle.test_energy > 0.0 && cycle.test_energy >= floor;
    if (!cycle.scored)
      continue;
    ++result.scored_cycles;
    result.max_cycle_energy_error = std::max(result.max_cycle_energy_error, cycle.energy_error());
    result.max_peak_tension_error =
        std::max(result.max_peak_tension_error, cycle.peak_tension_error());
    result.max_peak_compression_error =
        std::max(result.max_peak_compression_error, cycle.peak_compression_error());
    cycle.beta_compared = cycle.test_peaks.tension > 0.0 &&
                          cycle.test_peaks.tension >= options.beta_force_floor &&
                          cycle.test_peaks.compression >= options.beta_force_floor;
    if (cycle.beta_compared) {
      ++result.beta_cycles;
      // A model without positive force where the test has some has a NaN beta: the worst
      // difference.
      const double beta = cycle.beta_difference();
      result.max_beta_difference = std::isnan(beta) ? std::numeric_limits<double>::infinity()
                                                    : std::max(result.max_beta_difference, beta);
      // std::max keeps the first argument when the second is NaN
      result.largest_test_beta = std::max(result.largest_test_beta, cycle.test_beta);
      result.largest_model_beta = std::max(result.largest_model_beta, cycle.model_beta);
    }
    result.largest_test_tension = std::max(result.largest_test_tension, cycle.test_peaks.tension);
    result.largest_model_tension =
        std::max(result.largest_model_tension, cycle.model_peaks.tension);
  }

  double largest_test_work = 0.0;
  for (const CycleSpan& span : segment_excursions(deformation, options.reversal_threshold)) {
    ExcursionComparison excursion;
    excursion.span = span;
    excursion.test_work = loop_energy(deformation, test_force, span);
    excursion.model_work = loop_energy(deformation, model_force, span);
    excursion.test_peak = excursion_peak(deformation, test_force, span);
    excursion.model_peak = excursion_peak(deformation, model_force, span);
    largest_test_work = std::max(largest_test_work, std::abs(excursion.test_work));
    result.excursions.push_back(excursion);
  }
  const double work_floor = options.energy_floor_fraction * largest_test_work;
  for (ExcursionComparison& excursion : result.excursions) {
    excursion.scored =
        std::abs(excursion.test_work) > 0.0 && std::abs(excursion.test_work) >= work_floor;
    if (!excursion.scored)
      continue;
    ++result.scored_excursions;
    result.max_excursion_work_error =
        std::max(result.max_excursion_work_error, excursion.work_error());
    result.max_excursion_peak_error =
        std::max(result.max_excursion_peak_error, excursion.peak_error());
  }
  return result;
}

} // namespace brb::validation
