#include "brb/study/stress_run.hpp"

#include "brb/analysis/cyclic_test.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/model/brace_model.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <sstream>
#include <thread>

namespace brb::study {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// Counts the non-finite numbers it is shown.
class NanCounter {
public:
  void operator()(double value) {
    if (!std::isfinite(value))
      ++count_;
  }
  template <typename Range> void all(const Range& values) {
    for (const double value : values)
      (*this)(value);
  }
  int count() const { return count_; }

private:
  int count_ = 0;
};

void count_indicators(NanCounter& nan, const analysis::BraceIndicators& indicators) {
  nan(indicators.max_steel_damage);
  nan(indicators.max_mortar_damage);
  nan(indicators.max_core_lateral_displacement);
  nan(indicators.max_casing_lateral_displacement);
  nan(indicators.cumulative_inelastic_deformation);
}

/// The energy-balance error over `input` (N mm); the error itself when input is not > 0 (a
/// history that did no work has nothing to balance, and then any misfit is reported whole).
double relative_to(double error, double input) {
  return input > 0.0 ? std::abs(error) / input : std::abs(error);
}

void run_brace(const BraceStress& stress, StressResult& result) {
  model::BraceModel brace = stress.brace.element.fidelity == model::Fidelity::truss
                                ? model::build_brace_truss_model(stress.brace)
                                : model::build_brace_model(stress.brace);
  analysis::CyclicTest test(brace, stress.settings);
  result.planned_steps = static_cast<int>(stress.deformation.size()) - 1;
  // One point per follow(): the step is timed on its own. Cycle 0 for every point: the
  // stress suite asks for no per-cycle metrics.
  const int no_cycle = 0;
  const std::span<const int> cycle(&no_cycle, 1);
  for (std::size_t k = 1; k < stress.deformation.size(); ++k) {
    const auto started = Clock::now();
    const bool converged = test.follow(std::span<const double>(&stress.deformation[k], 1), cycle,
                                       std::span<const double>());
    if (!converged) {
      result.failed_step_wall_time = seconds_since(started);
      break;
    }
    result.step_wall_times.push_back(seconds_since(started));
  }
  const analysis::CyclicTestResult run = test.result();
  result.steps = static_cast<int>(run.steps.size()) - 1;
  result.completed = run.completed;
  result.failure_reason = run.stop_reason;

  NanCounter nan;
  for (const analysis::CyclicStep& step : run.steps) {
    nan(step.deformation);
    nan(step.force);
    nan(step.max_lateral_displacement);
  }
  const analysis::EnergyBalance& energy = run.energy_balance;
  nan.all(std::initializer_list<double>{energy.external_work, energy.stored, energy.dissipated,
                                        energy.released_in_jumps, energy.integration_misfit,
                                        energy.gross_work, run.energy_total, run.max_tension,
                                        run.max_compression});
  count_indicators(nan, run.indicators);
  result.nan_count = nan.count();

  // Over the gross work (the sum of |work| per substep, the README's relative_error): the
  // net work of nearly elastic cycles is close to zero, so an imbalance over it measures
  // nothing.
  const double imbalance = energy.external_work - energy.stored - energy.dissipated -
                           energy.integration_misfit - energy.released_in_jumps;
  result.input_work = energy.gross_work;
  result.energy_error = relative_to(imbalance, energy.gross_work);
  result.fallbacks.substeps = std::max(0, run.substeps - result.steps);
  result.fallbacks.pseudo_transient = run.regularised_steps;
  result.fallbacks.unstable_accepted = run.unstable_accepted;
  result.fallbacks.energy_cuts = run.energy_cuts;
  result.fallbacks.far_branch_cuts = run.far_branch_cuts;

  double deformation_reached = 0.0;
  double lateral = 0.0;
  for (const analysis::CyclicStep& step : run.steps) {
    if (std::abs(step.deformation) > std::abs(deformation_reached))
      deformation_reached = step.deformation;
    lateral = std::max(lateral, step.max_lateral_displacement);
  }
  std::ostringstream notes;
  notes.precision(4);
  notes << "net work " << energy.external_work << " N mm, imbalance " << imbalance
        << " N mm, integration misfit " << energy.integration_misfit << " N mm; peak deformation "
        << deformation_reached << " mm, forces " << run.max_compression << " / " << run.max_tension
        << " N, lateral " << lateral << " mm";
  if (run.indicators.max_mortar_damage > 0.0)
    notes << ", mortar damage " << run.indicators.max_mortar_damage;
  result.notes = notes.str();
}

void run_frame(const FrameStress& stress, StressResult& result) {
  frame::FrameModel model = frame::build_frame(stress.frame, stress.source, stress.braces);
  frame::FrameRunOptions options = frame::run_options_of(stress.frame);
  // Every recorder on, every brace recorded: all outputs are checked for NaN.
  options.recorders.drifts = !model.stories.empty();
  options.recorders.floor_accelerations = !model.floors.empty();
  options.recorders.base_shear = true;
  options.recorders.energy = true;
  options.recorders.braces.clear();
  for (const frame::BraceReference& brace : model.braces)
    options.recorders.braces.push_back(brace.id);
  options.record_step_wall_times = true;
  if (stress.drift_limit)
    options.drift_limit = *stress.drift_limit;
  analysis::GroundAcceleration component;
  component.direction = options.directions.front();
  component.dt = stress.dt;
  component.acceleration = stress.acceleration;
  if (!(options.dt > 0.0))
    options.dt = stress.dt;
  const double record_duration =
      stress.dt * static_cast<double>(stress.acceleration.size() - 1) + options.free_vibration;
  result.planned_steps = static_cast<int>(std::ceil(record_duration / options.dt - 1e-9));

  const frame::FrameRunResult run = frame::run_time_history(model, {component}, options);
  result.steps = run.steps;
  result.step_wall_times = run.step_wall_times;
  result.completed = run.gravity_converged && run.converged;
  result.collapsed = run.collapsed;
  if (!result.completed)
    result.failure_reason = run.stop_reason;

  NanCounter nan;
  for (const auto& [name, history] : run.histories) {
    for (const std::vector<double>& row : history.rows)
      nan.all(row);
  }
  nan.all(run.periods);
  nan.all(run.max_drift);
  nan.all(run.residual_drift);
  nan.all(run.peak_floor_acceleration);
  nan(run.peak_base_shear);
  const analysis::TransientEnergy& energy = run.energy;
  nan.all(std::initializer_list<double>{
      energy.input, energy.static_work, energy.kinetic, energy.damping, energy.stored,
      energy.dissipated, energy.integration_misfit, energy.gross_input, run.energy_balance_error});
  for (const frame::BraceSummary& brace : run.braces) {
    nan.all(std::initializer_list<double>{brace.max_tension, brace.max_compression,
                                          brace.max_core_strain,
                                          brace.cumulative_inelastic_deformation});
  }
  result.nan_count = nan.count();

  result.input_work = energy.input;
  result.energy_error = relative_to(energy.absolute_error(), energy.input);
  for (const analysis::FallbackRecord& fallback : run.fallbacks) {
    if (fallback.what.find("substeps") != std::string::npos)
      ++result.fallbacks.substeps;
    else if (fallback.what.find("modified Newton") != std::string::npos)
      ++result.fallbacks.modified_newton;
    else if (fallback.what.find("Broyden") != std::string::npos)
      ++result.fallbacks.broyden;
  }

  double peak_drift = 0.0;
  for (const double drift : run.max_drift)
    peak_drift = std::max(peak_drift, drift);
  double core_strain = 0.0;
  for (const frame::BraceSummary& brace : run.braces)
    core_strain = std::max(core_strain, brace.max_core_strain);
  result.peak_drift = peak_drift;
  std::ostringstream notes;
  notes.precision(4);
  notes << "peak drift " << 100.0 * peak_drift << " %, core strain " << 100.0 * core_strain
        << " %, t = " << run.end_time << " of " << run.duration << " s; integration misfit "
        << energy.integration_misfit << " N mm";
  result.notes = notes.str();
  if (run.collapsed)
    result.outcome = run.stop_reason;
}

} // namespace

StressResult run_stress_case(const StressCase& stress_case) {
  const auto started = Clock::now();
  StressResult result;
  result.name = stress_case.name;
  result.group = stress_case.group;
  try {
    if (const auto* brace = std::get_if<BraceStress>(&stress_case.subject))
      run_brace(*brace, result);
    else
      run_frame(std::get<FrameStress>(stress_case.subject), result);
  } catch (const std::exception& error) {
    // A case that throws has failed, and says why: it still reports.
    result.completed = false;
    result.failure_reason = std::string("exception: ") + error.what();
  }
  if (result.outcome.empty())
    result.outcome = result.completed ? "completed" : result.failure_reason;
  result.wall_time = seconds_since(started);
  return result;
}

std::vector<StressResult>
run_stress_cases(const std::vector<StressCase>& cases, int jobs,
                 const std::function<void(const StressResult&)>& finished) {
  std::vector<StressResult> results(cases.size());
  std::atomic<std::size_t> next{0};
  std::mutex report_mutex;
  const auto worker = [&] {
    for (std::size_t k = next++; k < cases.size(); k = next++) {
      results[k] = run_stress_case(cases[k]);
      if (finished) {
        const std::lock_guard lock(report_mutex);
        finished(results[k]);
      }
    }
  };
  const auto threads = static_cast<std::size_t>(std::max(jobs, 1));
  if (threads == 1) {
    worker();
    return results;
  }
  std::vector<std::jthread> pool;
  for (std::size_t t = 0; t < std::min(threads, cases.size()); ++t)
    pool.emplace_back(worker);
  pool.clear(); // joins
  return results;
}

} // namespace brb::study
