#include "brb/design/qualification.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace brb::design {
namespace {

/// Amplitudes are compared with Delta_by and 2 Delta_bm up to this relative tolerance (the
/// sequence's own amplitudes sit exactly on them).
constexpr double kAmplitudeTolerance = 1e-9;

/// The K3.4c step (1 to 6) of cycle `index` (1-based): two cycles per step 1-5, then 6.
int sequence_step_of(int index) {
  return std::min(6, (index + 1) / 2);
}

/// Cycles of `protocol` (whose first point is the unloaded 0) renumbered after
/// `cycles_done`, without that first point, followed by the test.
bool follow_protocol(analysis::CyclicTest& test, const io::LoadingProtocol& protocol,
                     int cycles_done, std::vector<double>& amplitudes) {
  std::vector<int> cycle(protocol.cycle.begin() + 1, protocol.cycle.end());
  for (int& c : cycle)
    c += cycles_done;
  amplitudes.insert(amplitudes.end(), protocol.cycle_amplitude.begin(),
                    protocol.cycle_amplitude.end());
  const std::vector<double> points(protocol.deformation.begin() + 1, protocol.deformation.end());
  return test.follow(points, cycle, amplitudes);
}

/// Per cycle: the largest fall of the force behind its running peak on a loading branch
/// (a run of steps moving the same way), in N.
std::vector<double> largest_force_drops(const analysis::CyclicTestResult& test, int cycles) {
  std::vector<double> drops(static_cast<std::size_t>(cycles), 0.0);
  int direction = 0;
  double peak = 0.0;
  for (std::size_t k = 1; k < test.steps.size(); ++k) {
    const analysis::CyclicStep& step = test.steps[k];
    const double move = step.deformation - test.steps[k - 1].deformation;
    const int step_direction = move > 0.0 ? 1 : (move < 0.0 ? -1 : 0);
    if (step_direction == 0)
      continue;
    if (step_direction != direction) {
      direction = step_direction;
      peak = test.steps[k - 1].force;
    }
    // Loading in tension: force should rise; in compression: fall.
    const double signed_force = direction * step.force;
    const double signed_peak = direction * peak;
    if (signed_force > signed_peak) {
      peak = step.force;
    } else if (step.cycle >= 1 && step.cycle <= cycles) {
      double& drop = drops[static_cast<std::size_t>(step.cycle - 1)];
      drop = std::max(drop, signed_peak - signed_force);
    }
  }
  return drops;
}

Criterion flag_criterion(std::string id, std::string description, bool raised, std::string note) {
  return {std::move(id), std::move(description), raised ? 1.0 : 0.0, 0.0, "flag",
          !raised,       std::move(note)};
}

Criterion bound_criterion(std::string id, std::string description, double value, double limit,
                          bool at_least, std::string note) {
  const bool passed = at_least ? value >= limit : value <= limit;
  return {std::move(id), std::move(description), value, limit, at_least ? ">=" : "<=",
          passed,        std::move(note)};
}

} // namespace

QualificationResult run_qualification(model::BraceModel& brace, const QualificationInput& input) {
  if (!(input.tested_yield_force > 0.0))
    throw std::invalid_argument("run_qualification: Pysc must be > 0 N");
  if (!(input.max_step > 0.0))
    throw std::invalid_argument("run_qualification: max_step must be > 0 mm");
  QualificationResult result;
  const double dby = brace.yield_deformation;
  const double dbm = input.design_deformation;
  result.sequence = qualification_sequence(dby, dbm, input.edition);
  result.estimated_extra_cycles = estimated_extra_cycles(result.sequence);

  analysis::CyclicTest test(brace, input.settings, /*record_history=*/true);
  std::vector<double> amplitudes;
  // One cycle at a time, so that the test stops at the end of the cycle in which the brace
  // failed (fracture, global buckling, casing failure: K3.8b), as a laboratory test ends.
  const auto brace_failed = [&test]() {
    const analysis::BraceIndicators& flags = test.indicators();
    return flags.core_fracture || flags.global_buckling || flags.casing_failure;
  };
  bool running = true;
  for (const io::CycleGroup& group : result.sequence.groups) {
    const io::LoadingProtocol one_cycle =
        io::cyclic_protocol("K3.4c", {{group.amplitude, 1}}, input.max_step);
    for (int c = 0; c < group.cycles && running; ++c) {
      if (brace_failed()) {
        result.stopped_at_failure = true;
        running = false;
        break;
      }
      running = follow_protocol(test, one_cycle, static_cast<int>(amplitudes.size()), amplitudes);
    }
  }
  // Step 6: one cycle at 1.5 Delta_bm at a time while the brace's own cumulative inelastic
  // deformation is short of the target (with a guard against a brace that stops yielding).
  const int most_extra = input.extra_cycle_factor * result.estimated_extra_cycles + 10;
  const io::LoadingProtocol extra_cycle =
      io::cyclic_protocol("K3.4c step 6", {{result.sequence.extra_amplitude, 1}}, input.max_step);
  while (running &&
         test.indicators().cumulative_inelastic_deformation < result.sequence.cumulative_target &&
         result.extra_cycles < most_extra) {
    if (brace_failed()) {
      result.stopped_at_failure = true;
      break;
    }
    running = follow_protocol(test, extra_cycle, static_cast<int>(amplitudes.size()), amplitudes);
    if (running)
      ++result.extra_cycles;
  }
  result.test = test.result();
  const analysis::CyclicTestResult& run = result.test;
  result.cumulative_target_reached =
      run.indicators.cumulative_inelastic_deformation >= result.sequence.cumulative_target;

  // Per cycle.
  const int cycle_count = static_cast<int>(run.cycles.size());
  const std::vector<double> drops = largest_force_drops(run, cycle_count);
  std::vector<double> cid_at_end(static_cast<std::size_t>(cycle_count), 0.0);
  for (std::size_t k = 0; k < run.steps.size() && k < run.history.size(); ++k) {
    const int c = run.steps[k].cycle;
    if (c >= 1 && c <= cycle_count)
      cid_at_end[static_cast<std::size_t>(c - 1)] =
          run.history[k].indicators.cumulative_inelastic_deformation;
  }
  const double pysc = input.tested_yield_force;
  for (const analysis::CycleMetrics& metrics : run.cycles) {
    QualificationCycle cycle;
    cycle.index = metrics.index;
    cycle.sequence_step = sequence_step_of(metrics.index);
    cycle.amplitude = metrics.amplitude;
    cycle.max_tension = std::max(0.0, metrics.max_tension);
    cycle.max_compression = std::max(0.0, -metrics.max_compression);
    cycle.beta = cycle.max_tension > 0.0 ? cycle.max_compression / cycle.max_tension : 0.0;
    cycle.omega = cycle.max_tension / pysc;
    cycle.cumulative_inelastic_deformation =
        cid_at_end[static_cast<std::size_t>(metrics.index - 1)];
    cycle.largest_force_drop = drops[static_cast<std::size_t>(metrics.index - 1)] / pysc;
    cycle.beyond_yield = metrics.amplitude > dby * (1.0 + kAmplitudeTolerance);
    cycle.in_adjustment_range =
        metrics.amplitude <= input.edition.adjustment_range * dbm * (1.0 + kAmplitudeTolerance);
    result.cycles.push_back(cycle);
  }

  // F4.2a: beta and omega over the cycles up to 2 Delta_bm; beta not less than 1.0.
  double min_tension_ratio = 0.0;
  double min_compression_ratio = 0.0;
  double max_beta = 0.0;
  double largest_drop = 0.0;
  bool first_beyond = true;
  for (const QualificationCycle& cycle : result.cycles) {
    largest_drop = std::max(largest_drop, cycle.largest_force_drop);
    if (!cycle.beyond_yield)
      continue;
    if (cycle.in_adjustment_range) {
      result.beta = std::max(result.beta, cycle.beta);
      result.omega = std::max(result.omega, cycle.omega);
    }
    const double tension_ratio = cycle.max_tension / pysc;
    const double compression_ratio = cycle.max_compression / pysc;
    min_tension_ratio = first_beyond ? tension_ratio : std::min(min_tension_ratio, tension_ratio);
    min_compression_ratio =
        first_beyond ? compression_ratio : std::min(min_compression_ratio, compression_ratio);
    max_beta = std::max(max_beta, cycle.beta);
    first_beyond = false;
  }

  // Core strain at the 2 Delta_bm peaks.
  const double peak = 2.0 * dbm;
  for (std::size_t k = 0; k < run.steps.size() && k < run.history.size(); ++k) {
    if (std::abs(std::abs(run.steps[k].deformation) - peak) <= 1e-9 * peak) {
      const double strain = run.history[k].core_strain;
      if (!result.core_strain_at_2dbm || std::abs(strain) > std::abs(*result.core_strain_at_2dbm))
        result.core_strain_at_2dbm = strain;
    }
  }

  // K3.8 acceptance criteria.
  std::vector<Criterion>& criteria = result.criteria;
  const bool sequence_run = run.completed && !result.stopped_at_failure;
  std::string completion_note = "completed";
  if (!run.completed) {
    completion_note = "the solver stopped: " + run.stop_reason;
  } else if (result.stopped_at_failure) {
    completion_note =
        "stopped after cycle " + std::to_string(run.cycles.size()) + ": the brace failed (K3.8b)";
  }
  criteria.push_back(flag_criterion(
      "completion", "the whole sequence was run (the solver passed every step, the brace held)",
      !sequence_run, completion_note));
  std::ostringstream cid_note;
  cid_note << result.extra_cycles << " cycles at 1.5 Delta_bm added (estimate "
           << result.estimated_extra_cycles << ")";
  criteria.push_back(bound_criterion(
      "K3.4c cumulative", "cumulative inelastic axial deformation reached (multiples of Delta_by)",
      run.indicators.cumulative_inelastic_deformation, result.sequence.cumulative_target, true,
      cid_note.str()));
  criteria.push_back(bound_criterion(
      "K3.8a stiffness",
      "positive incremental stiffness: largest fall of the force on a loading branch / Pysc",
      largest_drop, kStiffnessDropTolerance, false,
      "tolerance for round-off and high-mode snap-throughs (project choice)"));
  criteria.push_back(flag_criterion("K3.8b fracture", "no fracture of the core",
                                    run.indicators.core_fracture,
                                    "raised when a core fiber's damage reaches 0.9"));
  criteria.push_back(flag_criterion(
      "K3.8b instability", "no brace instability (global buckling)", run.indicators.global_buckling,
      "raised when the casing (or core) deflects laterally by more than L_y / 250"));
  criteria.push_back(
      flag_criterion("K3.8b casing", "no casing failure", run.indicators.casing_failure,
                     "raised when the mortar bearing damage under a station reaches 0.9; end "
                     "connections are not modelled as able to fail"));
  criteria.push_back(bound_criterion("K3.8c tension", "Tmax / Pysc in every cycle beyond Delta_by",
                                     min_tension_ratio, input.edition.minimum_strength_ratio, true,
                                     "smallest over the cycles beyond Delta_by"));
  criteria.push_back(bound_criterion(
      "K3.8c compression", "Pmax / Pysc in every cycle beyond Delta_by", min_compression_ratio,
      input.edition.minimum_strength_ratio, true, "smallest over the cycles beyond Delta_by"));
  criteria.push_back(bound_criterion("K3.8d beta", "Pmax / Tmax in every cycle beyond Delta_by",
                                     max_beta, input.beta_limit, false,
                                     input.edition.beta_limit_source));
  if (first_beyond) {
    // No cycle went beyond Delta_by: criteria c and d have nothing to judge.
    for (Criterion& criterion : criteria) {
      if (criterion.id.rfind("K3.8c", 0) == 0 || criterion.id == "K3.8d beta") {
        criterion.passed = false;
        criterion.note = "no completed cycle beyond Delta_by";
      }
    }
  }
  result.passed = std::all_of(criteria.begin(), criteria.end(),
                              [](const Criterion& criterion) { return criterion.passed; });
  return result;
}

std::string failed_criteria(const QualificationResult& result) {
  std::string text;
  for (const Criterion& criterion : result.criteria) {
    if (!criterion.passed)
      text += (text.empty() ? "" : ", ") + criterion.id;
  }
  return text;
}

} // namespace brb::design
