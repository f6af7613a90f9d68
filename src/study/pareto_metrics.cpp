#include "brb/study/pareto_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace brb::study {
namespace {

constexpr double kInfinite = std::numeric_limits<double>::infinity();

/// |value - reference| / |reference|; infinite when the reference is 0 and the value is not.
double relative(double value, double reference) {
  const double difference = std::abs(value - reference);
  if (reference == 0.0)
    return difference == 0.0 ? 0.0 : kInfinite;
  return difference / std::abs(reference);
}

double beta_of(const CycleResponse& cycle) {
  return cycle.max_tension > 0.0 ? std::abs(cycle.max_compression) / cycle.max_tension : 0.0;
}

double largest(const std::vector<double>& values) {
  double most = 0.0;
  for (const double value : values)
    most = std::max(most, std::abs(value));
  return most;
}

} // namespace

double ParetoErrors::primary() const {
  if (cycle_energy)
    return *cycle_energy;
  if (peak_drift)
    return *peak_drift;
  return kInfinite;
}

double ParetoErrors::worst() const {
  std::optional<double> most;
  for (const auto& metric : {cycle_energy, peak_force, beta, peak_drift, residual_drift, cid}) {
    if (metric)
      most = std::max(most.value_or(0.0), *metric);
  }
  return most.value_or(kInfinite);
}

ParetoErrors component_errors(const ComponentResponse& reference, const ComponentResponse& run) {
  ParetoErrors errors;
  if (run.cycles.size() < reference.cycles.size()) {
    errors.cycle_energy = errors.peak_force = errors.beta = kInfinite;
    return errors;
  }
  double largest_energy = 0.0;
  for (const CycleResponse& cycle : reference.cycles)
    largest_energy = std::max(largest_energy, cycle.energy);
  double energy = 0.0, force = 0.0, beta = 0.0;
  for (std::size_t i = 0; i < reference.cycles.size(); ++i) {
    const CycleResponse& ref = reference.cycles[i];
    const CycleResponse& got = run.cycles[i];
    force = std::max({force, relative(got.max_tension, ref.max_tension),
                      relative(got.max_compression, ref.max_compression)});
    if (largest_energy > 0.0 && ref.energy >= kSignificantCycleEnergy * largest_energy) {
      energy = std::max(energy, relative(got.energy, ref.energy));
      beta = std::max(beta, relative(beta_of(got), beta_of(ref)));
    }
  }
  errors.cycle_energy = energy;
  errors.peak_force = force;
  errors.beta = beta;
  return errors;
}

ParetoErrors frame_errors(const FrameResponse& reference, const FrameResponse& run) {
  ParetoErrors errors;
  if (run.end_time < reference.end_time * (1.0 - 1e-9) ||
      run.max_drift.size() != reference.max_drift.size() ||
      run.cid.size() != reference.cid.size()) {
    errors.peak_drift = errors.residual_drift = errors.cid = kInfinite;
    return errors;
  }
  const double peak_reference_drift = largest(reference.max_drift);
  double drift = 0.0, residual = 0.0, cid = 0.0;
  for (std::size_t s = 0; s < reference.max_drift.size(); ++s) {
    drift = std::max(drift, relative(run.max_drift[s], reference.max_drift[s]));
    residual =
        std::max(residual, peak_reference_drift > 0.0
                               ? std::abs(run.residual_drift[s] - reference.residual_drift[s]) /
                                     peak_reference_drift
                               : kInfinite);
  }
  const double cid_scale = std::max(largest(reference.cid), 1.0);
  for (std::size_t b = 0; b < reference.cid.size(); ++b)
    cid = std::max(cid, std::abs(run.cid[b] - reference.cid[b]) / cid_scale);
  errors.peak_drift = drift;
  errors.residual_drift = residual;
  errors.cid = cid;
  return errors;
}

std::optional<double> solid_cycle_energy_error(const ComponentResponse& solid,
                                               const ComponentResponse& run) {
  if (!run.completed || solid.cycles.size() < run.cycles.size())
    return std::nullopt;
  ComponentResponse compared = solid;
  compared.cycles.resize(run.cycles.size());
  for (std::size_t i = 0; i < run.cycles.size(); ++i) {
    if (relative(run.cycles[i].amplitude, compared.cycles[i].amplitude) > kSolidAmplitudeTolerance)
      return std::nullopt;
  }
  return component_errors(compared, run).cycle_energy;
}

} // namespace brb::study
