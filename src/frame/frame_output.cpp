#include "brb/frame/frame_output.hpp"

#include "brb/io/atomic_file.hpp"
#include "brb/io/csv.hpp"

namespace brb::frame {

using Json = nlohmann::ordered_json;

Json frame_summary_json(const FrameModel& frame, const FrameRunResult& result,
                        const FrameRunDescription& description) {
  Json summary = Json::object();
  summary["title"] = frame.title;
  summary["model"] = description.model_file;
  summary["motion"] = description.motion_file;
  summary["scale"] = description.scale;
  summary["integrator"] = description.integrator;
  summary["dt"] = description.dt;
  if (result.explicit_time_step > 0.0) {
    summary["explicit"] = Json{{"time_step", result.explicit_time_step},
                               {"added_mass_fraction", result.added_mass_fraction}};
  }
  summary["duration"] = result.duration;
  summary["end_time"] = result.end_time;
  summary["steps"] = result.steps;
  summary["converged"] = result.converged;
  summary["collapse"] = result.collapsed;
  summary["stop_reason"] = result.stop_reason;
  summary["periods"] = result.periods;
  Json stories = Json::array();
  for (const StoryReference& story : frame.stories)
    stories.push_back(story.name);
  summary["stories"] = stories;
  summary["max_drift"] = result.max_drift;
  summary["residual_drift"] = result.residual_drift;
  Json floors = Json::array();
  for (const FloorReference& floor : frame.floors)
    floors.push_back(floor.name);
  summary["floors"] = floors;
  summary["peak_floor_acceleration_g"] = result.peak_floor_acceleration;
  summary["peak_base_shear"] = result.peak_base_shear;
  summary["energy_input"] = result.energy.input;
  summary["energy_balance_error"] = result.energy_balance_error;
  summary["energy"] = Json{{"input", result.energy.input},
                           {"static_work", result.energy.static_work},
                           {"kinetic", result.energy.kinetic},
                           {"damping", result.energy.damping},
                           {"stored", result.energy.stored},
                           {"dissipated", result.energy.dissipated},
                           {"integration_misfit", result.energy.integration_misfit}};
  Json fallbacks = Json::array();
  for (const analysis::FallbackRecord& fallback : result.fallbacks)
    fallbacks.push_back(
        Json{{"time", fallback.time}, {"what", fallback.what}, {"reason", fallback.reason}});
  summary["fallbacks"] = fallbacks;
  Json braces = Json::array();
  for (const BraceSummary& brace : result.braces) {
    braces.push_back(Json{{"id", brace.id},
                          {"fidelity", brace.fidelity},
                          {"max_tension", brace.max_tension},
                          {"max_compression", brace.max_compression},
                          {"max_core_strain", brace.max_core_strain},
                          {"cid", brace.cumulative_inelastic_deformation},
                          {"core_fracture", brace.core_fracture},
                          {"casing_failure", brace.casing_failure},
                          {"global_buckling", brace.global_buckling}});
  }
  summary["braces"] = braces;
  summary["wall_time"] = description.wall_time;
  // null: each brace as its file meshes it
  summary["core_elements"] =
      description.core_elements ? nlohmann::ordered_json(*description.core_elements) : nullptr;
  summary["units"] = Json{
      {"force", "N"}, {"length", "mm"}, {"time", "s"}, {"energy", "N mm"}, {"acceleration", "g"}};
  return summary;
}

void write_frame_outputs(const std::filesystem::path& directory, const FrameModel& frame,
                         const FrameRunResult& result, const FrameRunDescription& description) {
  for (const auto& [name, history] : result.histories) {
    io::NumericTable table(history.columns);
    for (const std::vector<double>& row : history.rows)
      table.append_row(row);
    io::AtomicFile file(directory / (name + ".csv"));
    file.write(table.text());
    file.commit();
  }
  io::AtomicFile summary(directory / "summary.json");
  summary.write(frame_summary_json(frame, result, description).dump(2) + "\n");
  summary.commit();
}

} // namespace brb::frame
