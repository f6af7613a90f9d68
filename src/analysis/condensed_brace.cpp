#include "brb/analysis/condensed_brace.hpp"

#include "brb/model/brace_model.hpp"

#include <optional>

namespace brb::analysis {

std::unique_ptr<CondensedBraceModel> build_condensed_brace_model(const model::BraceSpec& spec,
                                                                 NewtonSettings settings) {
  auto result = std::make_unique<CondensedBraceModel>();
  model::Model& model = result->model;
  result->start_node = model.add_node(element::Vector3::Zero());
  result->end_node = model.add_node(element::Vector3(spec.total_length(), 0.0, 0.0));
  result->element = &model.add_element(std::make_unique<BRBElement>(
      std::array<int, 2>{result->start_node, result->end_node},
      model.coordinates(result->start_node), model.coordinates(result->end_node), spec,
      std::nullopt, settings));
  model::hold_stand_alone_ends(model, result->start_node, result->end_node, spec.ends);
  return result;
}

CyclicTestResult run_condensed_cyclic_test(CondensedBraceModel& brace,
                                           std::span<const double> deformation,
                                           std::span<const int> cycle,
                                           std::span<const double> cycle_amplitude,
                                           NewtonSettings settings) {
  StaticAnalysis analysis(brace.model, settings);
  analysis.use_displacement_control(brace.end_node, model::ux);
  CyclicTestResult result;
  result.steps.push_back({0, cycle.empty() ? 0 : cycle[0], 0.0, 0.0, 0.0, 0});
  HysteresisAccumulator hysteresis(result);
  for (std::size_t k = 1; k < deformation.size(); ++k) {
    const StepReport report = analysis.step_to(deformation[k]);
    if (!report.converged) {
      result.stop_reason = step_failure(static_cast<int>(k), deformation[k], report.failure);
      break;
    }
    const CyclicStep step{static_cast<int>(k),      cycle[k], analysis.control_value(),
                          analysis.control_force(), 0.0,      report.substeps};
    const bool cycle_ends = k + 1 == deformation.size() || cycle[k + 1] != step.cycle;
    hysteresis.append(step, cycle_ends, cycle_amplitude);
  }
  record_solver_statistics(analysis, result);
  return result;
}

} // namespace brb::analysis
