#include "brb/study/stress_result.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace brb::study {

std::string_view group_name(StressGroup group) {
  switch (group) {
  case StressGroup::random_history:
    return "random_history";
  case StressGroup::monotonic_compression:
    return "monotonic_compression";
  case StressGroup::step_size:
    return "step_size";
  case StressGroup::frame_collapse:
    return "frame_collapse";
  case StressGroup::near_singular:
    return "near_singular";
  }
  return "unknown";
}

const std::vector<StressGroup>& all_stress_groups() {
  static const std::vector<StressGroup> groups{
      StressGroup::random_history, StressGroup::monotonic_compression, StressGroup::step_size,
      StressGroup::frame_collapse, StressGroup::near_singular};
  return groups;
}

TimeDistribution distribution_of(std::vector<double> times) {
  TimeDistribution distribution;
  if (times.empty())
    return distribution;
  std::sort(times.begin(), times.end());
  // Nearest rank: the smallest value with at least p n values at or below it.
  const auto rank = [&](double p) {
    const auto k = static_cast<std::size_t>(std::ceil(p * static_cast<double>(times.size())));
    return times[std::clamp<std::size_t>(k, 1, times.size()) - 1];
  };
  distribution.median = rank(0.5);
  distribution.p90 = rank(0.9);
  distribution.max = times.back();
  return distribution;
}

std::string StressResult::acceptance_failure() const {
  std::ostringstream why;
  if (nan_count != 0)
    why << nan_count << " non-finite numbers in the outputs; ";
  if (!completed && failure_reason.empty())
    why << "did not complete and gave no reason; ";
  if (!(energy_error < kEnergyErrorLimit))
    why << "energy-balance error " << energy_error << " >= " << kEnergyErrorLimit
        << " of the input work; ";
  std::string text = why.str();
  if (!text.empty())
    text.resize(text.size() - 2);
  return text;
}

bool StressResult::acceptable() const {
  return acceptance_failure().empty();
}

} // namespace brb::study
