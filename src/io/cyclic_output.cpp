#include "brb/io/cyclic_output.hpp"

#include <array>
#include <utility>

namespace brb::io {

using Json = nlohmann::ordered_json;

int converged_steps(const analysis::CyclicTestResult& result) {
  return result.steps.empty() ? 0 : static_cast<int>(result.steps.size()) - 1;
}

NumericTable hysteresis_table(const analysis::CyclicTestResult& result) {
  NumericTable table(
      {"step", "cycle", "deformation", "force", "max_lateral_displacement", "substeps"});
  for (const analysis::CyclicStep& step : result.steps) {
    table.append_row(std::array{static_cast<double>(step.step), static_cast<double>(step.cycle),
                                step.deformation, step.force, step.max_lateral_displacement,
                                static_cast<double>(step.substeps)});
  }
  return table;
}

Json cyclic_summary_json(const std::string& brace_name, double yield_deformation,
                         double yield_force, const analysis::CyclicTestResult& result) {
  Json cycles = Json::array();
  for (const analysis::CycleMetrics& cycle : result.cycles) {
    cycles.push_back(Json{{"index", cycle.index},
                          {"amplitude", cycle.amplitude},
                          {"energy", cycle.energy},
                          {"max_tension", cycle.max_tension},
                          {"max_compression", cycle.max_compression}});
  }
  const analysis::EnergyBalance& balance = result.energy_balance;
  Json summary = Json::object();
  summary["brace"] = brace_name;
  summary["yield_deformation"] = yield_deformation;
  summary["yield_force"] = yield_force;
  summary["max_tension"] = result.max_tension;
  summary["max_compression"] = result.max_compression;
  summary["energy_total"] = result.energy_total;
  summary["cycles"] = std::move(cycles);
  summary["completed"] = result.completed;
  summary["stop_reason"] = result.completed ? Json(nullptr) : Json(result.stop_reason);
  summary["solver"] = Json{{"steps", converged_steps(result)},
                           {"iterations", result.iterations},
                           {"substeps", result.substeps},
                           {"regularised_steps", result.regularised_steps},
                           {"unstable_accepted", result.unstable_accepted},
                           {"energy_cuts", result.energy_cuts},
                           {"far_branch_cuts", result.far_branch_cuts},
                           {"energy_tolerance_missed", result.energy_tolerance_missed},
                           {"assemblies", result.work.assemblies},
                           {"line_search_assemblies", result.work.line_search_assemblies},
                           {"converged_newton_iterations", result.work.converged_newton_iterations},
                           {"failed_newton_iterations", result.work.failed_newton_iterations},
                           {"failed_newton_calls", result.work.failed_newton_calls},
                           {"pseudo_time_steps", result.work.pseudo_time_steps},
                           {"pseudo_time_iterations", result.work.pseudo_time_iterations}};
  if (result.resumed_from_step > 0) { // a run taken up from a checkpoint (README, "Checkpoints")
    summary["solver"]["resumed_from_step"] = result.resumed_from_step;
    summary["solver"]["seconds_before_resume"] = result.seconds_before_resume;
  }
  summary["energy_balance"] = Json{{"external_work", balance.external_work},
                                   {"stored", balance.stored},
                                   {"dissipated", balance.dissipated},
                                   {"integration_misfit", balance.integration_misfit},
                                   {"released_in_jumps", balance.released_in_jumps},
                                   {"released_by_laws", balance.released_by_laws},
                                   {"gross_work", balance.gross_work},
                                   {"relative_error", balance.relative_error()},
                                   {"law_relative_error", balance.law_relative_error()},
                                   {"relative_misfit", balance.relative_misfit()}};
  const analysis::BraceIndicators& indicators = result.indicators;
  summary["element"] =
      Json{{"max_steel_damage", indicators.max_steel_damage},
           {"max_mortar_damage", indicators.max_mortar_damage},
           {"max_bearing_damage", indicators.max_bearing_damage},
           {"min_bearing_residual_strength", indicators.min_bearing_residual_strength},
           {"min_fill_residual_strength", indicators.min_fill_residual_strength},
           {"max_core_lateral_displacement", indicators.max_core_lateral_displacement},
           {"max_casing_lateral_displacement", indicators.max_casing_lateral_displacement},
           {"max_buckling_half_waves", indicators.max_buckling_half_waves},
           {"cumulative_inelastic_deformation", indicators.cumulative_inelastic_deformation},
           {"uniform_axial_strain_beams", indicators.uniform_axial_strain_beams},
           {"core_fracture", indicators.core_fracture},
           {"casing_failure", indicators.casing_failure},
           {"global_buckling", indicators.global_buckling}};
  summary["units"] = Json{{"force", "N"}, {"length", "mm"}};
  return summary;
}

NumericTable element_history_table(const analysis::CyclicTestResult& result) {
  NumericTable table({"step", "core_strain", "dissipated_energy",
                      "cumulative_inelastic_deformation", "max_core_lateral_displacement",
                      "max_casing_lateral_displacement", "max_buckling_half_waves",
                      "max_steel_damage", "max_mortar_damage", "min_bearing_residual_strength",
                      "core_fracture", "casing_failure", "global_buckling"});
  for (const analysis::ElementHistoryPoint& point : result.history) {
    const analysis::BraceIndicators& indicators = point.indicators;
    table.append_row(std::array{
        static_cast<double>(point.step), point.core_strain, point.dissipated_energy,
        indicators.cumulative_inelastic_deformation, indicators.max_core_lateral_displacement,
        indicators.max_casing_lateral_displacement,
        static_cast<double>(indicators.max_buckling_half_waves), indicators.max_steel_damage,
        indicators.max_mortar_damage, indicators.min_bearing_residual_strength,
        indicators.core_fracture ? 1.0 : 0.0, indicators.casing_failure ? 1.0 : 0.0,
        indicators.global_buckling ? 1.0 : 0.0});
  }
  return table;
}

NumericTable brace_shape_table(const analysis::CyclicTestResult& result) {
  NumericTable table({"step", "node", "position", "lateral_y", "lateral_z", "station",
                      "casing_lateral_y", "casing_lateral_z", "bearing_force_y", "bearing_force_z",
                      "mortar_damage", "friction_force", "wave_normal_force", "core_axial_force",
                      "core_axial_strain", "casing_axial_force"});
  for (const analysis::BraceShapeNode& point : result.shapes) {
    table.append_row(std::array{
        static_cast<double>(point.step), static_cast<double>(point.node), point.position,
        point.lateral_y, point.lateral_z, point.station ? 1.0 : 0.0, point.casing_lateral_y,
        point.casing_lateral_z, point.bearing_force_y, point.bearing_force_z, point.mortar_damage,
        point.friction_force, point.wave_normal_force, point.core_axial_force,
        point.core_axial_strain, point.casing_axial_force});
  }
  return table;
}

} // namespace brb::io
