#include "brb/analysis/cyclic_test.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <utility>

namespace brb::analysis {
CyclicTestResult run_cyclic_test(model::BraceModel& brace, std::span<const double> deformation,
                                 std::span<const int> cycle,
                                 std::span<const double> cycle_amplitude, NewtonSettings settings,
                                 bool record_history) {
  CyclicTestResult result;
  StaticAnalysis analysis(brace.model, settings);
  analysis.use_displacement_control(brace.end_node, model::ux);
  BraceIndicatorTracker tracker(brace, brace.model);
  const BraceIndicatorTracker::Positions position = [&](int node) -> const element::Vector3& {
    return analysis.node(node).position;
  };

  result.steps.push_back({0, cycle.empty() ? 0 : cycle[0], 0.0, 0.0, 0.0, 0});
  // The yielding core's end nodes, for its mean strain (none for the truss fidelity).
  std::optional<std::pair<int, int>> yielding_ends;
  for (std::size_t e = 0; e < brace.in_yielding_zone.size(); ++e) {
    if (!brace.in_yielding_zone[e])
      continue;
    if (!yielding_ends)
      yielding_ends = {brace.nodes[e], brace.nodes[e + 1]};
    yielding_ends->second = brace.nodes[e + 1];
  }
  const auto core_strain = [&]() {
    if (brace.truss != nullptr)
      return brace.truss->core_strain();
    if (!yielding_ends)
      return 0.0;
    const double initial = (brace.model.coordinates(yielding_ends->second) -
                            brace.model.coordinates(yielding_ends->first))
                               .norm();
    const double current =
        (position(yielding_ends->second) - position(yielding_ends->first)).norm();
    return (current - initial) / initial;
  };
  if (record_history)
    result.history.push_back({0, 0.0, 0.0, tracker.indicators()});
  CycleMetrics current;
  for (std::size_t k = 1; k < deformation.size(); ++k) {
    const StepReport report = analysis.step_to(deformation[k]);
    if (!report.converged) {
      std::ostringstream reason;
      reason << "step " << k << " (deformation " << std::setprecision(6) << deformation[k]
             << " mm): " << report.failure;
      result.stop_reason = reason.str();
      break;
    }
    CyclicStep step{static_cast<int>(k),
                    cycle[k],
                    analysis.control_value(),
                    analysis.control_force(),
                    tracker.max_lateral_displacement(position),
                    report.substeps};
    const CyclicStep& previous = result.steps.back();
    tracker.observe(position, step.deformation, step.force);
    if (record_history) {
      const EnergyBalance& energy = analysis.energy();
      result.history.push_back({step.step, core_strain(),
                                energy.dissipated + energy.released_in_jumps,
                                tracker.indicators()});
    }
    const double work =
        0.5 * (step.force + previous.force) * (step.deformation - previous.deformation);
    result.energy_total += work;
    result.max_tension = std::max(result.max_tension, step.force);
    result.max_compression = std::min(result.max_compression, step.force);

    if (step.cycle != current.index) {
      current = CycleMetrics{};
      current.index = step.cycle;
      if (step.cycle >= 1 && static_cast<std::size_t>(step.cycle) <= cycle_amplitude.size()) {
        current.amplitude = cycle_amplitude[step.cycle - 1];
      }
    }
    current.energy += work;
    current.max_tension = std::max(current.max_tension, step.force);
    current.max_compression = std::min(current.max_compression, step.force);
    const bool cycle_ends = k + 1 == deformation.size() || cycle[k + 1] != step.cycle;
    if (cycle_ends && step.cycle >= 1)
      result.cycles.push_back(current);
    result.steps.push_back(step);
  }
  result.completed = result.stop_reason.empty();
  result.energy_balance = analysis.energy();
  result.iterations = analysis.total_iterations();
  result.substeps = analysis.total_substeps();
  result.regularised_steps = analysis.regularised_steps();
  result.unstable_accepted = analysis.unstable_accepted();
  result.energy_cuts = analysis.energy_cuts();
  result.energy_tolerance_missed = analysis.energy_tolerance_missed();
  result.indicators = tracker.indicators();
  return result;
}

} // namespace brb::analysis
