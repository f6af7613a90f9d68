#include "brb/validation/metric_kinds.hpp"

#include "brb/io/csv.hpp"
#include "brb/validation/record_comparison.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <sstream>
#include <string>

namespace brb::validation {
namespace {

using Json = nlohmann::json;
using analysis::CyclicStep;

// ---------------------------------------------------------------------------------------
// Parameters shared by several kinds

/// A whole number >= 1 (a cycle index).
int positive_whole_number(const io::JsonValue& value, std::string_view meaning) {
  const double number = value.number(meaning);
  if (!(number >= 1.0 && number == std::floor(number) && number < 1e9)) {
    throw value.error(std::string(meaning) + " must be a whole number >= 1 (got " +
                      io::describe_json_value(value.json()) + ")");
  }
  return static_cast<int>(number);
}

/// One of `allowed`, else an error listing them.
std::string one_of(const io::JsonValue& value, std::string_view meaning,
                   std::span<const std::string_view> allowed) {
  const std::string text = value.string(meaning);
  std::string list;
  for (const std::string_view option : allowed) {
    if (text == option)
      return text;
    list += (list.empty() ? "\"" : ", \"") + std::string(option) + "\"";
  }
  throw value.error(std::string(meaning) + " must be one of " + list + " (got \"" + text + "\")");
}

/// The cycle selector: "cycle" (k, 1-based) or "amplitude_dy" (the first cycle whose
/// amplitude is that multiple of dy); at most one, and one when `required`.
void check_cycle_selector(const io::JsonValue& metric, bool required) {
  const std::optional<io::JsonValue> cycle = metric.find("cycle");
  const std::optional<io::JsonValue> amplitude = metric.find("amplitude_dy");
  if (cycle && amplitude)
    throw amplitude->error("give either \"cycle\" or \"amplitude_dy\", not both");
  if (cycle)
    positive_whole_number(*cycle, "cycle index (1-based)");
  if (amplitude) {
    const double value = amplitude->number("cycle amplitude in multiples of dy");
    if (!(value > 0.0))
      throw amplitude->error("cycle amplitude in multiples of dy must be > 0");
  }
  if (required && !cycle && !amplitude) {
    throw metric.error("missing the cycle: give \"cycle\" (index, 1-based) or \"amplitude_dy\" "
                       "(the first cycle at that amplitude, in multiples of dy)");
  }
}

constexpr std::array<std::string_view, 2> kDirections{"tension", "compression"};

void check_direction(const io::JsonValue& metric) {
  one_of(metric.at("direction", "direction of the force, \"tension\" or \"compression\""),
         "direction", kDirections);
}

// ---------------------------------------------------------------------------------------
// Reading a hysteresis

/// Two amplitudes are the same protocol amplitude when within this relative difference (a
/// protocol in dy converted to mm and back is exact to round-off; 1 % also accepts amplitudes
/// written in mm with a few digits).
constexpr double kAmplitudeMatch = 0.01;

/// The points of cycle `index` in result.steps: [first, last], `first` being the point
/// before the cycle (its start, the previous cycle's end), so that the cycle's increments are
/// (first, last]; its own points, over which peaks are taken, are [own_first, last].
struct CycleSpan {
  std::size_t first = 0;
  std::size_t own_first = 0;
  std::size_t last = 0;
  std::string label; ///< "cycle 8 (5.00 dy)"
};

std::string format_fixed(double value, int decimals) {
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(decimals);
  text << value;
  return text.str();
}

/// The span of a completed cycle, or a note on why there is none.
struct CycleLookup {
  std::optional<CycleSpan> span;
  std::string note;
};

CycleLookup find_cycle(const Json& metric, const RunData& run) {
  const std::vector<analysis::CycleMetrics>& cycles = run.result.cycles;
  const analysis::CycleMetrics* chosen = nullptr;
  if (metric.contains("cycle")) {
    const int index = metric.at("cycle").get<int>();
    for (const analysis::CycleMetrics& cycle : cycles) {
      if (cycle.index == index)
        chosen = &cycle;
    }
    if (chosen == nullptr)
      return {std::nullopt, "cycle " + std::to_string(index) + " was not completed"};
  } else {
    const double amplitude_dy = metric.at("amplitude_dy").get<double>();
    for (const analysis::CycleMetrics& cycle : cycles) {
      const double ratio = cycle.amplitude / run.yield_deformation;
      if (std::abs(ratio - amplitude_dy) <= kAmplitudeMatch * amplitude_dy) {
        chosen = &cycle;
        break;
      }
    }
    if (chosen == nullptr) {
      return {std::nullopt, "no completed cycle at " + format_fixed(amplitude_dy, 2) + " dy"};
    }
  }
  const std::vector<CyclicStep>& steps = run.result.steps;
  const auto in_cycle = [&](const CyclicStep& step) { return step.cycle == chosen->index; };
  const auto begin = std::find_if(steps.begin(), steps.end(), in_cycle);
  if (begin == steps.end() || begin == steps.begin())
    return {std::nullopt, "cycle " + std::to_string(chosen->index) + " has no points"};
  const auto end = std::find_if_not(begin, steps.end(), in_cycle);
  CycleSpan span;
  span.first = static_cast<std::size_t>(begin - steps.begin()) - 1;
  span.own_first = span.first + 1;
  span.last = static_cast<std::size_t>(end - steps.begin()) - 1;
  span.label = "cycle " + std::to_string(chosen->index) + " (" +
               format_fixed(chosen->amplitude / run.yield_deformation, 2) + " dy)";
  return {span, ""};
}

/// The points a peak is taken over: a cycle's, or every point of the run (no selector).
CycleLookup points_of(const Json& metric, const RunData& run) {
  if (metric.contains("cycle") || metric.contains("amplitude_dy"))
    return find_cycle(metric, run);
  if (run.result.steps.empty())
    return {std::nullopt, "the run has no points"};
  return {CycleSpan{0, 0, run.result.steps.size() - 1, "whole run"}, ""};
}

struct Peaks {
  double tension = 0.0;     ///< largest force (N)
  double compression = 0.0; ///< magnitude of the smallest force (N)
};

Peaks peaks_over(const std::vector<CyclicStep>& steps, const CycleSpan& span) {
  Peaks peaks{-HUGE_VAL, -HUGE_VAL};
  for (std::size_t i = span.own_first; i <= span.last; ++i) {
    peaks.tension = std::max(peaks.tension, steps[i].force);
    peaks.compression = std::max(peaks.compression, -steps[i].force);
  }
  return peaks;
}

// ---------------------------------------------------------------------------------------
// The kinds: one check and one evaluation each

void check_cycle_energy(const io::JsonValue& metric) {
  check_cycle_selector(metric, true);
}

/// Loop energy: the integral of force d(deformation) over the cycle's increments,
/// trapezoidal (the same rule as summary.json's cycle energy).
MetricValue evaluate_cycle_energy(const Json& metric, const RunData& run) {
  const CycleLookup lookup = find_cycle(metric, run);
  if (!lookup.span)
    return {std::nullopt, lookup.note};
  const std::vector<CyclicStep>& steps = run.result.steps;
  double energy = 0.0;
  for (std::size_t i = lookup.span->first + 1; i <= lookup.span->last; ++i) {
    energy += 0.5 * (steps[i].force + steps[i - 1].force) *
              (steps[i].deformation - steps[i - 1].deformation);
  }
  return {energy, lookup.span->label};
}

void check_peak_force(const io::JsonValue& metric) {
  check_direction(metric);
  check_cycle_selector(metric, false);
}

/// The largest force magnitude in the direction asked, in a cycle or over the run.
MetricValue evaluate_peak_force(const Json& metric, const RunData& run) {
  const CycleLookup lookup = points_of(metric, run);
  if (!lookup.span)
    return {std::nullopt, lookup.note};
  const Peaks peaks = peaks_over(run.result.steps, *lookup.span);
  const bool tension = metric.at("direction").get<std::string>() == "tension";
  return {tension ? peaks.tension : peaks.compression, lookup.span->label};
}

void check_compression_tension_ratio(const io::JsonValue& metric) {
  check_cycle_selector(metric, false);
}

/// beta = Pmax / Tmax (AISC 341's compression strength adjustment factor): the largest
/// compression over the largest tension, in a cycle or over the run.
MetricValue evaluate_compression_tension_ratio(const Json& metric, const RunData& run) {
  const CycleLookup lookup = points_of(metric, run);
  if (!lookup.span)
    return {std::nullopt, lookup.note};
  const Peaks peaks = peaks_over(run.result.steps, *lookup.span);
  if (!(peaks.tension > 0.0))
    return {std::nullopt, lookup.span->label + ": no tension force"};
  return {peaks.compression / peaks.tension, lookup.span->label};
}

void check_yield_force(const io::JsonValue& metric) {
  check_direction(metric);
  const io::JsonValue offset =
      metric.at("offset_core_strain",
                "offset strain of the core for the offset yield definition, e.g. 0.002");
  const double value = offset.number("offset strain of the core");
  if (!(value >= 0.0 && value < 0.1))
    throw offset.error("offset strain of the core must be >= 0 and < 0.1");
}

/// Offset yield force: where the force-deformation path first crosses the line through
/// (+/- offset, 0) with the brace's elastic stiffness K0 = Py / dy, the offset being
/// offset_core_strain x the yielding length (the 0.2 % offset rule of tensile tests applied to
/// the core, the only part that yields). In tension: the first point with
/// F <= K0 (delta - offset); in compression: the first with F >= K0 (delta + offset). The
/// crossing is interpolated linearly between the two points around it.
MetricValue evaluate_yield_force(const Json& metric, const RunData& run) {
  const bool tension = metric.at("direction").get<std::string>() == "tension";
  const double sign = tension ? 1.0 : -1.0;
  const double stiffness = run.yield_force / run.yield_deformation;
  const double offset = metric.at("offset_core_strain").get<double>() * run.yielding_length;
  // Signed distance above the offset line (in the direction of loading): > 0 before the
  // crossing, <= 0 at and after it.
  const auto above = [&](const CyclicStep& step) {
    return sign * (step.force - stiffness * (step.deformation - sign * offset));
  };
  const std::vector<CyclicStep>& steps = run.result.steps;
  for (std::size_t i = 1; i < steps.size(); ++i) {
    const double before = above(steps[i - 1]);
    const double after = above(steps[i]);
    if (before > 0.0 && after <= 0.0) {
      const double weight = before / (before - after);
      const double force = steps[i - 1].force + weight * (steps[i].force - steps[i - 1].force);
      return {sign * force, "step " + std::to_string(steps[i].step) + " (offset " +
                                format_fixed(offset, 3) + " mm)"};
    }
  }
  return {std::nullopt, std::string("the path never crossed the ") +
                            (tension ? "tension" : "compression") + " offset line"};
}

constexpr std::array<std::string_view, 3> kFlags{"core_fracture", "casing_failure",
                                                 "global_buckling"};

void check_flag(const io::JsonValue& metric) {
  one_of(metric.at("flag", "the flag of summary.json's element block"), "flag", kFlags);
}

/// An element flag of summary.json: 1 when raised, 0 when not.
MetricValue evaluate_flag(const Json& metric, const RunData& run) {
  const std::string flag = metric.at("flag").get<std::string>();
  const analysis::BraceIndicators& indicators = run.result.indicators;
  const bool raised = flag == "core_fracture"    ? indicators.core_fracture
                      : flag == "casing_failure" ? indicators.casing_failure
                                                 : indicators.global_buckling;
  return {raised ? 1.0 : 0.0, flag};
}

constexpr std::array<std::string_view, 9> kIndicators{"max_steel_damage",
                                                      "max_mortar_damage",
                                                      "max_bearing_damage",
                                                      "min_bearing_residual_strength",
                                                      "min_fill_residual_strength",
                                                      "max_core_lateral_displacement",
                                                      "max_casing_lateral_displacement",
                                                      "max_buckling_half_waves",
                                                      "cumulative_inelastic_deformation"};

void check_max_indicator(const io::JsonValue& metric) {
  one_of(metric.at("indicator", "the indicator of summary.json's element block"), "indicator",
         kIndicators);
}

/// A running-extreme indicator of summary.json's element block: the largest over the run, or
/// for the residual strengths the smallest.
MetricValue evaluate_max_indicator(const Json& metric, const RunData& run) {
  const std::string name = metric.at("indicator").get<std::string>();
  const analysis::BraceIndicators& indicators = run.result.indicators;
  double value = indicators.cumulative_inelastic_deformation;
  if (name == "max_steel_damage")
    value = indicators.max_steel_damage;
  else if (name == "max_mortar_damage")
    value = indicators.max_mortar_damage;
  else if (name == "max_bearing_damage")
    value = indicators.max_bearing_damage;
  else if (name == "min_bearing_residual_strength")
    value = indicators.min_bearing_residual_strength;
  else if (name == "min_fill_residual_strength")
    value = indicators.min_fill_residual_strength;
  else if (name == "max_core_lateral_displacement")
    value = indicators.max_core_lateral_displacement;
  else if (name == "max_casing_lateral_displacement")
    value = indicators.max_casing_lateral_displacement;
  else if (name == "max_buckling_half_waves")
    value = indicators.max_buckling_half_waves;
  return {value, name};
}

void check_cycle_energy_spread(const io::JsonValue& metric) {
  const int first = positive_whole_number(metric.at("first_cycle", "first cycle (1-based)"),
                                          "first cycle (1-based)");
  const io::JsonValue last_value = metric.at("last_cycle", "last cycle (1-based)");
  const int last = positive_whole_number(last_value, "last cycle (1-based)");
  if (!(last > first))
    throw last_value.error("the last cycle must come after the first");
}

/// (largest - smallest) / mean of the loop energies of cycles first..last: how stable a
/// series of equal cycles is (summary.json's cycle energies, trapezoidal).
MetricValue evaluate_cycle_energy_spread(const Json& metric, const RunData& run) {
  const int first = metric.at("first_cycle").get<int>();
  const int last = metric.at("last_cycle").get<int>();
  std::vector<double> energies;
  for (const analysis::CycleMetrics& cycle : run.result.cycles) {
    if (cycle.index >= first && cycle.index <= last)
      energies.push_back(cycle.energy);
  }
  const std::string label = "cycles " + std::to_string(first) + " to " + std::to_string(last);
  if (energies.size() != static_cast<std::size_t>(last - first + 1))
    return {std::nullopt, label + ": not all were completed"};
  const auto [smallest, largest] = std::minmax_element(energies.begin(), energies.end());
  double mean = 0.0;
  for (const double energy : energies)
    mean += energy / static_cast<double>(energies.size());
  if (!(mean > 0.0))
    return {std::nullopt, label + ": no energy dissipated"};
  return {(*largest - *smallest) / mean, label};
}

void check_residual_compression_ratio(const io::JsonValue& metric) {
  check_cycle_selector(metric, false);
}

/// The compression force at the point of largest shortening over the peak compression (in
/// a cycle or over the run): 1 when the brace holds its strength to the end of the
/// excursion, near 0 when it lost it (a failed casing, global buckling).
MetricValue evaluate_residual_compression_ratio(const Json& metric, const RunData& run) {
  const CycleLookup lookup = points_of(metric, run);
  if (!lookup.span)
    return {std::nullopt, lookup.note};
  const std::vector<CyclicStep>& steps = run.result.steps;
  std::size_t shortest = lookup.span->own_first;
  for (std::size_t i = lookup.span->own_first; i <= lookup.span->last; ++i) {
    if (steps[i].deformation < steps[shortest].deformation)
      shortest = i;
  }
  const Peaks peaks = peaks_over(steps, *lookup.span);
  if (!(peaks.compression > 0.0) || !(steps[shortest].deformation < 0.0))
    return {std::nullopt, lookup.span->label + ": no compression"};
  return {-steps[shortest].force / peaks.compression,
          lookup.span->label + ", at " + format_fixed(steps[shortest].deformation, 3) + " mm"};
}

void check_nothing(const io::JsonValue&) {}

/// The model against the specimen's lab record at the points both have (model step k is
/// protocol point k), with record_comparison.hpp's three metrics.
struct RecordLookup {
  std::optional<RecordComparison> comparison;
  std::string note;
};

RecordLookup compare_run_with_record(const RunData& run) {
  if (run.record == nullptr)
    return {std::nullopt, "the specimen has no reference"};
  const RecordSeries& record = *run.record;
  const std::vector<CyclicStep>& steps = run.result.steps;
  if (steps.size() > record.deformation.size())
    return {std::nullopt, "the model took more points than the protocol has"};
  std::vector<double> deformation, test_force, model_force;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    if (std::isnan(record.test_force[k]))
      continue;
    deformation.push_back(record.deformation[k]);
    test_force.push_back(record.test_force[k]);
    model_force.push_back(steps[k].force);
  }
  if (deformation.empty())
    return {std::nullopt, "no point of the reference was reached"};
  const std::string note = std::to_string(deformation.size()) + " reference points" +
                           (run.result.completed ? "" : " (the run stopped early)");
  try {
    // beta is compared on cycles whose test peaks both reach the core's yield force
    // (RecordComparisonOptions::beta_force_floor)
    return {compare_with_record(
                deformation, test_force, model_force,
                {record.reversal_threshold, record.energy_floor_fraction, run.yield_force}),
            note};
  } catch (const std::invalid_argument& error) {
    return {std::nullopt, error.what()};
  }
}

MetricValue evaluate_record_nrms(const Json&, const RunData& run) {
  const RecordLookup lookup = compare_run_with_record(run);
  if (!lookup.comparison)
    return {std::nullopt, lookup.note};
  return {lookup.comparison->normalised_rms_error, lookup.note};
}

/// The compared cycle a record kind is asked about ("compared_cycle": k-th cycle of the
/// comparison, 1-based, maximum to maximum), or nothing for "the worst scored cycle".
std::optional<std::size_t> compared_cycle(const Json& metric) {
  if (!metric.contains("compared_cycle"))
    return std::nullopt;
  return metric.at("compared_cycle").get<std::size_t>();
}

void check_compared_cycle(const io::JsonValue& metric) {
  if (const auto cycle = metric.find("compared_cycle"))
    positive_whole_number(*cycle, "compared cycle (1-based, maximum to maximum)");
}

/// The worst scored cycle's value (`worst`), or the value of the one cycle asked for
/// (`of_cycle`, whether scored or not: a cycle named explicitly is judged), with a note;
/// `lookup` is compare_run_with_record of the run.
template <typename Worst, typename OfCycle>
MetricValue record_cycle_value(const Json& metric, const RecordLookup& lookup, Worst worst,
                               OfCycle of_cycle) {
  if (!lookup.comparison)
    return {std::nullopt, lookup.note};
  const RecordComparison& comparison = *lookup.comparison;
  std::optional<double> value;
  std::string note;
  if (const auto k = compared_cycle(metric)) {
    if (*k > comparison.cycles.size()) {
      return {std::nullopt, lookup.note + ": compared cycle " + std::to_string(*k) +
                                " does not exist (" + std::to_string(comparison.cycles.size()) +
                                " cycles)"};
    }
    CycleComparison cycle = comparison.cycles[*k - 1];
    note = lookup.note + ", compared cycle " + std::to_string(*k);
    // A cycle asked for by name is judged even below the energy floor, but not without a
    // reference loop (its relative errors are undefined).
    cycle.scored = cycle.test_energy > 0.0;
    if (!cycle.scored)
      return {std::nullopt, note + ": the reference's loop has no energy"};
    value = of_cycle(cycle);
  } else {
    if (comparison.scored_cycles == 0)
      return {std::nullopt, lookup.note + ": no cycle scored"};
    value = worst(comparison);
    note = lookup.note + ", " + std::to_string(comparison.scored_cycles) + " cycles";
  }
  if (!std::isfinite(*value))
    return {std::nullopt, note + ": a compared cycle has no peak in a direction"};
  return {value, note};
}

void check_record_cycle_kind(const io::JsonValue& metric) {
  check_compared_cycle(metric);
}

MetricValue evaluate_record_cycle_energy(const Json& metric, const RunData& run) {
  return record_cycle_value(
      metric, compare_run_with_record(run),
      [](const RecordComparison& c) { return c.max_cycle_energy_error; },
      [](const CycleComparison& c) { return c.energy_error(); });
}

/// Beta is compared only on scored cycles whose reference peaks both reach the yield force
/// (CycleComparison::beta_compared): elsewhere there is no beta to match, and a record
/// without such a cycle gives no value rather than a zero difference. A cycle named by
/// "compared_cycle" is judged wherever the reference has a tension peak in it.
MetricValue evaluate_record_beta(const Json& metric, const RunData& run) {
  const RecordLookup lookup = compare_run_with_record(run);
  const std::optional<std::size_t> k = compared_cycle(metric);
  if (lookup.comparison) {
    const RecordComparison& comparison = *lookup.comparison;
    if (!k && comparison.scored_cycles > 0 && comparison.beta_cycles == 0) {
      return {std::nullopt, lookup.note + ": no scored cycle of the reference reaches the "
                                          "yield force in both directions (beta undefined)"};
    }
    if (k && *k <= comparison.cycles.size() &&
        !(comparison.cycles[*k - 1].test_peaks.tension > 0.0)) {
      return {std::nullopt, lookup.note + ": compared cycle " + std::to_string(*k) +
                                " of the reference has no tension peak (beta undefined)"};
    }
  }
  MetricValue value = record_cycle_value(
      metric, lookup, [](const RecordComparison& c) { return c.max_beta_difference; },
      [](CycleComparison c) {
        c.beta_compared = true;
        return c.beta_difference();
      });
  if (value.value && !k && lookup.comparison)
    value.note += " (" + std::to_string(lookup.comparison->beta_cycles) +
                  " reaching the yield force both ways)";
  return value;
}

/// |model - reference| of an AISC 341 adjustment factor from a test (F4.2a, as `brb check`
/// takes it: the largest over the cycles), `model` and `reference` read from the comparison's
/// scored cycles, with both values in the note.
template <typename Model, typename Reference>
MetricValue record_factor_difference(const RunData& run, Model model, Reference reference) {
  const RecordLookup lookup = compare_run_with_record(run);
  if (!lookup.comparison)
    return {std::nullopt, lookup.note};
  const RecordComparison& comparison = *lookup.comparison;
  if (comparison.scored_cycles == 0)
    return {std::nullopt, lookup.note + ": no cycle scored"};
  const double model_value = model(comparison);
  const double reference_value = reference(comparison);
  std::string note = lookup.note + ", " + std::to_string(comparison.scored_cycles) +
                     " cycles: model " + io::significant(model_value, 4) + ", reference " +
                     io::significant(reference_value, 4);
  if (!(model_value > 0.0))
    return {std::nullopt, note + ": no scored cycle of the model has a tension peak"};
  return {std::abs(model_value - reference_value), note};
}

/// beta = the largest Pmax / Tmax over the scored cycles.
MetricValue evaluate_record_largest_beta(const Json&, const RunData& run) {
  return record_factor_difference(
      run, [](const RecordComparison& c) { return c.largest_model_beta; },
      [](const RecordComparison& c) { return c.largest_test_beta; });
}

void check_record_largest_omega(const io::JsonValue& metric) {
  const io::JsonValue pysc =
      metric.at("pysc", "the core's specified yield force A_c f_ysc (N), omega's denominator");
  const double value = pysc.number("the core's specified yield force A_c f_ysc (N)");
  if (!(value > 0.0 && std::isfinite(value)))
    throw pysc.error("the core's specified yield force A_c f_ysc must be > 0 (N)");
}

/// omega = the largest tension peak over the scored cycles over Pysc.
MetricValue evaluate_record_largest_omega(const Json& metric, const RunData& run) {
  const double pysc = metric.at("pysc").get<double>();
  const auto omega = [pysc](double tension) { return tension / pysc; };
  return record_factor_difference(
      run, [&](const RecordComparison& c) { return omega(c.largest_model_tension); },
      [&](const RecordComparison& c) { return omega(c.largest_test_tension); });
}

void check_record_peak_force(const io::JsonValue& metric) {
  if (const auto direction = metric.find("direction"))
    one_of(*direction, "direction", kDirections);
  check_compared_cycle(metric);
}

/// Relative error of the cycle's peak force in "direction" (tension, compression; absent:
/// the larger of the two).
MetricValue evaluate_record_peak_force(const Json& metric, const RunData& run) {
  const std::string direction =
      metric.contains("direction") ? metric.at("direction").get<std::string>() : "";
  const bool tension = direction != "compression";
  const bool compression = direction != "tension";
  return record_cycle_value(
      metric, compare_run_with_record(run),
      [&](const RecordComparison& c) {
        return std::max(tension ? c.max_peak_tension_error : 0.0,
                        compression ? c.max_peak_compression_error : 0.0);
      },
      [&](const CycleComparison& c) {
        return std::max(tension ? c.peak_tension_error() : 0.0,
                        compression ? c.peak_compression_error() : 0.0);
      });
}

/// The worst scored excursion's value (excursions: segment_excursions; the half cycles of a
/// protocol that closes no cycle), with a note.
template <typename Worst> MetricValue record_excursion_value(const RunData& run, Worst worst) {
  const RecordLookup lookup = compare_run_with_record(run);
  if (!lookup.comparison)
    return {std::nullopt, lookup.note};
  const RecordComparison& comparison = *lookup.comparison;
  if (comparison.scored_excursions == 0)
    return {std::nullopt, lookup.note + ": no excursion scored"};
  const double value = worst(comparison);
  const std::string note =
      lookup.note + ", " + std::to_string(comparison.scored_excursions) + " excursions";
  if (!std::isfinite(value))
    return {std::nullopt, note + ": a reference excursion has no peak in its direction"};
  return {value, note};
}

MetricValue evaluate_record_excursion_work(const Json&, const RunData& run) {
  return record_excursion_value(
      run, [](const RecordComparison& c) { return c.max_excursion_work_error; });
}

MetricValue evaluate_record_excursion_peak(const Json&, const RunData& run) {
  return record_excursion_value(
      run, [](const RecordComparison& c) { return c.max_excursion_peak_error; });
}

/// Cycles the model's failure may be away from the reference's by default ("within one
/// cycle", issue 6).
constexpr int kDefaultFailureCycleTolerance = 1;

void check_record_failure_mode(const io::JsonValue& metric) {
  if (const auto tolerance = metric.find("cycle_tolerance")) {
    const double value = tolerance->number("cycle tolerance (whole cycles)");
    if (!(value >= 0.0 && value == std::floor(value) && value < 1e6))
      throw tolerance->error("cycle tolerance must be a whole number of cycles >= 0");
  }
}

/// 1 when the model fails in the reference's mode within the cycle tolerance (or neither
/// fails), else 0.
MetricValue evaluate_record_failure_mode(const Json& metric, const RunData& run) {
  if (run.record == nullptr || !run.record->failure)
    return {std::nullopt, "the reference states no failure"};
  const std::optional<FailureEvent> model = model_failure(run.result);
  if (!model)
    return {std::nullopt, "the model raised a flag but its step history was not recorded"};
  const int tolerance = metric.contains("cycle_tolerance") ? metric.at("cycle_tolerance").get<int>()
                                                           : kDefaultFailureCycleTolerance;
  const FailureComparison comparison = compare_failures(*model, *run.record->failure, tolerance);
  return {comparison.agrees ? 1.0 : 0.0, comparison.description + " (within " +
                                             std::to_string(tolerance) + " cycle" +
                                             (tolerance == 1 ? "" : "s") + ")"};
}

const std::array<MetricKind, 17>& registry() {
  static const std::array<MetricKind, 17> kinds{{
      {"cycle_energy",
       "loop energy (N mm) of cycle k (\"cycle\") or of the first cycle at an amplitude "
       "(\"amplitude_dy\")",
       {"cycle", "amplitude_dy"},
       false,
       check_cycle_energy,
       evaluate_cycle_energy},
      {"peak_force",
       "largest force magnitude (N) in \"direction\" tension or compression, in a cycle "
       "(\"cycle\" or \"amplitude_dy\") or over the run",
       {"direction", "cycle", "amplitude_dy"},
       false,
       check_peak_force,
       evaluate_peak_force},
      {"compression_tension_ratio",
       "beta = Pmax / Tmax, in a cycle (\"cycle\" or \"amplitude_dy\") or over the run",
       {"cycle", "amplitude_dy"},
       false,
       check_compression_tension_ratio,
       evaluate_compression_tension_ratio},
      {"yield_force",
       "offset yield force (N) in \"direction\", offset \"offset_core_strain\" x yielding "
       "length, elastic slope Py / dy",
       {"direction", "offset_core_strain"},
       false,
       check_yield_force,
       evaluate_yield_force},
      {"flag",
       "an element flag of summary.json (\"flag\"), compared with \"expected\"",
       {"flag"},
       true,
       check_flag,
       evaluate_flag},
      {"max_indicator",
       "a running-extreme indicator of summary.json's element block (\"indicator\": the "
       "largest over the run, the smallest for a residual strength)",
       {"indicator"},
       false,
       check_max_indicator,
       evaluate_max_indicator},
      {"cycle_energy_spread",
       "(largest - smallest) / mean loop energy of cycles \"first_cycle\" to \"last_cycle\"",
       {"first_cycle", "last_cycle"},
       false,
       check_cycle_energy_spread,
       evaluate_cycle_energy_spread},
      {"residual_compression_ratio",
       "compression force at the largest shortening over the peak compression, in a cycle "
       "(\"cycle\" or \"amplitude_dy\") or over the run",
       {"cycle", "amplitude_dy"},
       false,
       check_residual_compression_ratio,
       evaluate_residual_compression_ratio},
      {"record_nrms",
       "normalised RMS force error against the specimen's reference (RMS of the difference "
       "over the RMS of the reference force, at the compared points)",
       {},
       false,
       check_nothing,
       evaluate_record_nrms},
      {"record_cycle_energy",
       "largest relative loop-energy error per scored cycle against the reference (or of "
       "\"compared_cycle\")",
       {"compared_cycle"},
       false,
       check_record_cycle_kind,
       evaluate_record_cycle_energy},
      {"record_beta",
       "largest |beta model - beta reference| per scored cycle (or of \"compared_cycle\")",
       {"compared_cycle"},
       false,
       check_record_cycle_kind,
       evaluate_record_beta},
      {"record_largest_beta",
       "|model - reference| of AISC 341's beta from a test: the largest Pmax / Tmax over the "
       "scored cycles",
       {},
       false,
       check_nothing,
       evaluate_record_largest_beta},
      {"record_largest_omega",
       "|model - reference| of AISC 341's omega from a test: the largest tension peak over the "
       "scored cycles over \"pysc\" (N, the core's A_c f_ysc)",
       {"pysc"},
       false,
       check_record_largest_omega,
       evaluate_record_largest_omega},
      {"record_peak_force",
       "largest relative error of the peak force per scored cycle (or of \"compared_cycle\"), "
       "in \"direction\" tension or compression, or the larger of both",
       {"direction", "compared_cycle"},
       false,
       check_record_peak_force,
       evaluate_record_peak_force},
      {"record_excursion_work",
       "largest relative error of the work F d(delta) per scored excursion (reversal to "
       "reversal, the first and last points counting as reversals) against the reference",
       {},
       false,
       check_nothing,
       evaluate_record_excursion_work},
      {"record_excursion_peak_force",
       "largest relative error of the peak force per scored excursion, in the excursion's "
       "direction (tension while elongating, compression while shortening)",
       {},
       false,
       check_nothing,
       evaluate_record_excursion_peak},
      {"record_failure_mode",
       "1 when the model fails in the reference's failure mode within \"cycle_tolerance\" "
       "cycles (default 1) of the reference's cycle, or neither fails",
       {"cycle_tolerance"},
       true,
       check_record_failure_mode,
       evaluate_record_failure_mode},
  }};
  return kinds;
}

} // namespace

std::span<const MetricKind> metric_kinds() {
  return registry();
}

const MetricKind* find_metric_kind(std::string_view name) {
  for (const MetricKind& kind : registry()) {
    if (kind.name == name)
      return &kind;
  }
  return nullptr;
}

std::string metric_kind_names() {
  std::string names;
  for (const MetricKind& kind : registry())
    names += (names.empty() ? "" : ", ") + std::string(kind.name);
  return names;
}

} // namespace brb::validation
