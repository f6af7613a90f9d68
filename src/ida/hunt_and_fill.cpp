#include "brb/ida/hunt_and_fill.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

namespace brb::ida {
namespace {

void require(bool ok, const char* field, const char* expected, double value) {
  if (ok)
    return;
  std::ostringstream message;
  message.precision(17);
  message << "hunt-and-fill settings: " << field << " must be " << expected << ", got " << value;
  throw std::invalid_argument(message.str());
}

void check_settings(const HuntFillSettings& s) {
  require(std::isfinite(s.first_intensity) && s.first_intensity > 0.0, "first_intensity",
          "a finite number > 0", s.first_intensity);
  require(std::isfinite(s.step) && s.step > 0.0, "step", "a finite number > 0", s.step);
  require(std::isfinite(s.step_growth) && s.step_growth >= 0.0, "step_growth",
          "a finite number >= 0", s.step_growth);
  require(std::isfinite(s.resolution) && s.resolution > 0.0, "resolution", "a finite number > 0",
          s.resolution);
  require(s.max_runs >= 1, "max_runs", "an integer >= 1", s.max_runs);
  require(std::isfinite(s.max_intensity) &&
              (s.max_intensity == 0.0 || s.max_intensity >= s.first_intensity),
          "max_intensity", "0 (no limit) or a finite number >= first_intensity", s.max_intensity);
}

std::optional<double> lowest_collapse_of(const std::vector<TracedRun>& runs) {
  std::optional<double> lowest;
  for (const TracedRun& run : runs) {
    if (run.collapsed && (!lowest || run.intensity < *lowest))
      lowest = run.intensity;
  }
  return lowest;
}

/// The non-collapsing intensities below the lowest collapse (all of them when nothing
/// collapsed), ascending: the points of the IDA curve below its flatline. Survivals above the
/// lowest collapse ("resurrection", V&C 2002 sec. 4) are not part of it.
std::vector<double> survivals_below(const std::vector<TracedRun>& runs,
                                    std::optional<double> ceiling) {
  std::vector<double> survivals;
  for (const TracedRun& run : runs) {
    if (!run.collapsed && (!ceiling || run.intensity < *ceiling))
      survivals.push_back(run.intensity);
  }
  std::sort(survivals.begin(), survivals.end());
  return survivals;
}

/// Hunting intensity number k (0-based): IM_0 = first, IM_{k+1} = IM_k + step + k growth
/// (V&C 2004, "hunt & fill"). Summed in one fixed order, so it is bitwise reproducible.
double hunting_intensity(const HuntFillSettings& s, std::size_t k) {
  double intensity = s.first_intensity;
  for (std::size_t j = 0; j < k; ++j)
    intensity += s.step + static_cast<double>(j) * s.step_growth;
  return intensity;
}

/// The midpoint of (low, high) when the interval is wider than `resolution` and the midpoint
/// is representable strictly inside it (so that no intensity is asked twice).
std::optional<double> midpoint_if_wider(double low, double high, double resolution) {
  if (!(high - low > resolution))
    return std::nullopt;
  const double middle = 0.5 * (low + high);
  if (!(middle > low && middle < high))
    return std::nullopt;
  return middle;
}

/// Gaps within this relative difference count as equally wide, so that round-off in the
/// hunting sums (0.55 - 0.35 against 1.0 - 0.8) does not decide between them.
constexpr double kEqualGaps = 1e-9;

/// Fill: the midpoint of the widest gap between successive survivals that is wider than
/// `resolution`; among equally wide gaps the lowest.
std::optional<double> fill_intensity(const std::vector<double>& survivals, double resolution) {
  std::optional<double> best;
  double widest = 0.0;
  for (std::size_t i = 1; i < survivals.size(); ++i) {
    const double gap = survivals[i] - survivals[i - 1];
    if (gap > widest * (1.0 + kEqualGaps)) {
      if (const auto middle = midpoint_if_wider(survivals[i - 1], survivals[i], resolution)) {
        widest = gap;
        best = middle;
      }
    }
  }
  return best;
}

} // namespace

HuntAndFill::HuntAndFill(const HuntFillSettings& settings) : settings_(settings) {
  check_settings(settings_);
  plan_next();
}

std::optional<double> HuntAndFill::next_intensity() const {
  return next_;
}

void HuntAndFill::record(double intensity, bool collapsed) {
  if (!next_) {
    throw std::logic_error("hunt-and-fill: a run was recorded at intensity " +
                           std::to_string(intensity) + " after the trace was complete");
  }
  if (std::bit_cast<std::uint64_t>(intensity) != std::bit_cast<std::uint64_t>(*next_)) {
    std::ostringstream message;
    message.precision(17);
    message << "hunt-and-fill: a run was recorded at intensity " << intensity
            << " but the tracer asked for " << *next_;
    throw std::logic_error(message.str());
  }
  runs_.push_back({intensity, collapsed});
  plan_next();
}

std::optional<double> HuntAndFill::lowest_collapse() const {
  return lowest_collapse_of(runs_);
}

std::optional<double> HuntAndFill::highest_survival() const {
  const std::vector<double> survivals = survivals_below(runs_, lowest_collapse());
  if (survivals.empty())
    return std::nullopt;
  return survivals.back();
}

// The next intensity follows from the settings and the runs alone (no other state), in this
// order of priority: budget; an unresolved collapse bracket (bisection); hunting; fill.
void HuntAndFill::plan_next() {
  next_.reset();
  if (runs_.size() >= static_cast<std::size_t>(settings_.max_runs))
    return;

  const std::optional<double> collapse = lowest_collapse();
  const std::vector<double> survivals = survivals_below(runs_, collapse);
  if (collapse) {
    // Bisection between the highest survival below the collapse and the collapse; when no run
    // below it survived (the first run collapsed) the lower end is 0, so the intensity is
    // halved until a run survives.
    const double low = survivals.empty() ? 0.0 : survivals.back();
    next_ = midpoint_if_wider(low, *collapse, settings_.resolution);
    if (!next_)
      next_ = fill_intensity(survivals, settings_.resolution);
    return;
  }

  // No collapse yet: until a run reaches max_intensity every run is a hunting run (run k at
  // IM_k), afterwards the budget fills.
  const bool limited = settings_.max_intensity > 0.0;
  const bool limit_reached =
      limited && std::any_of(runs_.begin(), runs_.end(), [&](const TracedRun& run) {
        return run.intensity >= settings_.max_intensity;
      });
  if (!limit_reached) {
    const double hunt = hunting_intensity(settings_, runs_.size());
    next_ = limited ? std::min(hunt, settings_.max_intensity) : hunt;
    return;
  }
  next_ = fill_intensity(survivals, settings_.resolution);
}

} // namespace brb::ida
