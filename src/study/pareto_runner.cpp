#include "brb/study/pareto_runner.hpp"

#include "brb/analysis/condensed_brace.hpp"
#include "brb/analysis/cyclic_test.hpp"
#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"
#include "brb/io/json_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/model/brace_fidelity.hpp"
#include "brb/model/brace_model.hpp"
#include "brb/study/pareto_front.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>
#include <variant>

namespace brb::study {
namespace {

using Clock = std::chrono::steady_clock;

/// Default step of a component test without max_step: dy / 10 (as `brb cyclic`).
constexpr double kDefaultMaxStepInDy = 0.1;

/// The inputs of a case, read once before any run (every input error shows first).
struct CaseInputs {
  model::BraceSpec brace;              ///< component
  std::optional<SolidReference> solid; ///< component, when the matrix names one
  model::FrameSpec frame;              ///< frame
  analysis::GroundAcceleration ground; ///< frame: the window of the record
};

/// The analysis step of a frame case without a setting's dt: the model's analysis.dt, or the
/// record's step when the model gives none (as `brb frame`).
double analysis_step(const CaseInputs& inputs) {
  const double model_step = frame::run_options_of(inputs.frame).dt;
  return model_step > 0.0 ? model_step : inputs.ground.dt;
}

/// The core element count every brace file of a frame gives, or nothing when they differ (or
/// the frame has no brace).
std::optional<int> file_core_elements(const model::FrameSpec& frame) {
  std::optional<int> count;
  for (const model::FrameElementSpec& element : frame.elements) {
    const auto* brace = std::get_if<model::BraceElementSpec>(&element.kind);
    if (!brace)
      continue;
    if (count && *count != brace->brace.core_elements)
      return std::nullopt;
    count = brace->brace.core_elements;
  }
  return count;
}

/// One run's result.
struct RunResult {
  double wall_time = 0.0;
  std::string built_as;
  std::string auto_reason;
  ComponentResponse component;
  FrameResponse frame;
  std::string stop_reason;
  double yield_deformation = 0.0;
};

model::Fidelity component_fidelity(const model::BraceSpec& brace, SettingFidelity fidelity,
                                   std::string& reason) {
  if (fidelity == SettingFidelity::truss)
    return model::Fidelity::truss;
  if (fidelity == SettingFidelity::full)
    return model::Fidelity::full;
  const model::FidelityChoice choice = model::choose_auto_fidelity(brace);
  reason = choice.reason;
  return choice.fidelity;
}

RunResult run_component(const ParetoCase& study_case, const CaseInputs& inputs,
                        const ParetoSetting& setting) {
  RunResult run;
  const model::BraceSpec brace = setting.applied_to(inputs.brace);
  const auto started = Clock::now();
  const model::Fidelity fidelity = component_fidelity(brace, setting.fidelity, run.auto_reason);
  // Condensed: the brace as one BRBElement between its outer nodes
  // (analysis/condensed_brace.hpp); otherwise the expanded brace model (or the truss).
  const bool condensed =
      fidelity == model::Fidelity::full && setting.mode == model::ElementMode::condensed;
  std::optional<model::BraceModel> built;
  std::unique_ptr<analysis::CondensedBraceModel> element;
  if (condensed)
    element = analysis::build_condensed_brace_model(brace);
  else
    built.emplace(fidelity == model::Fidelity::truss ? model::build_brace_truss_model(brace)
                                                     : model::build_brace_model(brace));
  const double dy =
      condensed ? element->element->internal_brace().yield_deformation : built->yield_deformation;
  // Not timed: the protocol is the same input for every setting (it depends on dy only).
  const auto protocol_started = Clock::now();
  const io::LoadingProtocol protocol = io::read_protocol(
      study_case.protocol, dy, dy * setting.max_step.value_or(kDefaultMaxStepInDy));
  const auto protocol_read = Clock::now();
  const analysis::CyclicTestResult result =
      condensed ? analysis::run_condensed_cyclic_test(*element, protocol.deformation,
                                                      protocol.cycle, protocol.cycle_amplitude)
                : analysis::run_cyclic_test(*built, protocol.deformation, protocol.cycle,
                                            protocol.cycle_amplitude);
  run.wall_time = std::chrono::duration<double>(Clock::now() - started).count() -
                  std::chrono::duration<double>(protocol_read - protocol_started).count();
  run.built_as = fidelity == model::Fidelity::truss ? "truss" : "full";
  run.yield_deformation = dy;
  run.component.completed = result.completed;
  run.component.iterations = result.iterations;
  for (const analysis::CycleMetrics& cycle : result.cycles)
    run.component.cycles.push_back(
        {cycle.energy, cycle.max_tension, cycle.max_compression, cycle.amplitude});
  run.stop_reason = result.stop_reason;
  return run;
}

frame::BraceOverride override_of(SettingFidelity fidelity) {
  switch (fidelity) {
  case SettingFidelity::truss:
    return frame::BraceOverride::truss;
  case SettingFidelity::full:
    return frame::BraceOverride::full;
  case SettingFidelity::automatic:
    return frame::BraceOverride::automatic;
  }
  return frame::BraceOverride::none;
}

RunResult run_frame(const ParetoCase& study_case, const CaseInputs& inputs,
                    const ParetoSetting& setting) {
  RunResult run;
  model::FrameSpec spec = inputs.frame;
  for (model::FrameElementSpec& element : spec.elements) {
    if (auto* brace = std::get_if<model::BraceElementSpec>(&element.kind)) {
      brace->brace = setting.applied_to(brace->brace);
      brace->mode = setting.mode;
    }
  }
  frame::FrameRunOptions options = frame::run_options_of(spec);
  options.recorders = frame::RecorderRequest{false, false, false, false, {}};
  options.dt = setting.dt.value_or(analysis_step(inputs));
  const auto started = Clock::now();
  frame::FrameModel built =
      frame::build_frame(spec, study_case.model.string(), override_of(setting.fidelity));
  const frame::FrameRunResult result = frame::run_time_history(built, {inputs.ground}, options);
  run.wall_time = std::chrono::duration<double>(Clock::now() - started).count();
  for (const frame::BraceReference& brace : built.braces) {
    (brace.fidelity == "truss" ? run.frame.truss_braces : run.frame.full_braces) += 1;
    if (run.auto_reason.empty() && !brace.fidelity_reason.empty())
      run.auto_reason = brace.fidelity_reason;
  }
  run.built_as = std::to_string(run.frame.truss_braces) + " truss; " +
                 std::to_string(run.frame.full_braces) + " full";
  run.frame.completed = result.converged && !result.collapsed;
  run.frame.end_time = result.end_time;
  run.frame.max_drift = result.max_drift;
  run.frame.residual_drift = result.residual_drift;
  for (const frame::BraceSummary& brace : result.braces)
    run.frame.cid.push_back(brace.cumulative_inelastic_deformation);
  if (result.stop_reason != "completed")
    run.stop_reason = result.stop_reason;
  return run;
}

} // namespace

SolidReference read_solid_reference(const std::filesystem::path& summary_file) {
  const nlohmann::json document = io::read_json_file(summary_file);
  const io::JsonValue root(document, summary_file.string());
  SolidReference reference;
  reference.file = summary_file;
  const io::JsonValue solid = root.at("solid", "the block a brb solid run writes");
  reference.run_seconds = solid.at("run_seconds", "the run's wall time, s").number("run time, s");
  const io::JsonValue completed = root.at("completed", "whether the run completed");
  if (!completed.json().is_boolean())
    throw completed.error("true or false");
  reference.response.completed = completed.json().get<bool>();
  const io::JsonValue cycles = root.at("cycles", "the run's completed cycles");
  const std::size_t count = cycles.expect_array(100000, "the run's completed cycles");
  for (std::size_t i = 0; i < count; ++i) {
    const io::JsonValue cycle = cycles.element(i);
    reference.response.cycles.push_back(
        {cycle.at("energy", "N mm").number("loop energy, N mm"),
         cycle.at("max_tension", "N").number("largest tension, N"),
         cycle.at("max_compression", "N").number("largest compression, N"),
         cycle.at("amplitude", "mm").number("cycle amplitude, mm")});
  }
  return reference;
}

namespace {

/// The last two components of a path ("brbf9/model.json"): what a committed run's model
/// path, written relative to wherever it ran, must share with the matrix's.
std::string folder_and_name(const std::filesystem::path& path) {
  return (path.parent_path().filename() / path.filename()).generic_string();
}

/// |a - b| within a relative 1e-9 of the larger (numbers written and read back as JSON).
bool same_number(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

std::vector<double> numbers_of(const io::JsonValue& array, std::string_view meaning) {
  std::vector<double> values;
  const std::size_t count = array.expect_array(100000, meaning);
  for (std::size_t i = 0; i < count; ++i)
    values.push_back(array.element(i).number(meaning));
  return values;
}

bool boolean_of(const io::JsonValue& value) {
  if (!value.json().is_boolean())
    throw value.error("true or false");
  return value.json().get<bool>();
}

} // namespace

CommittedFrameRun read_committed_frame_run(const std::filesystem::path& summary_file,
                                           const ParetoCase& study_case,
                                           const ParetoSetting& setting,
                                           const FrameRunExpectation& expected) {
  const nlohmann::json document = io::read_json_file(summary_file);
  const io::JsonValue root(document, summary_file.string());
  const auto mismatch = [&](const io::JsonValue& value, const std::string& expected) {
    return value.error("the committed run of setting \"" + setting.label + "\" must be " +
                       expected + " (got " + io::describe_json_value(value.json()) + ")");
  };
  const io::JsonValue model = root.at("model", "the frame model file of the run");
  if (folder_and_name(model.string("model file")) != folder_and_name(study_case.model))
    throw mismatch(model, "of the matrix's model, " + folder_and_name(study_case.model));
  const io::JsonValue motion = root.at("motion", "the ground-motion record of the run");
  if (std::filesystem::path(motion.string("record file")).filename() !=
      study_case.motion.filename())
    throw mismatch(motion, "under the matrix's record, " + study_case.motion.filename().string());
  const io::JsonValue scale = root.at("scale", "the factor on the record");
  if (!same_number(scale.number("scale factor"), study_case.scale))
    throw mismatch(scale, "at the matrix's scale " + io::format_number(study_case.scale));
  const io::JsonValue duration = root.at("duration", "the window analysed, s");
  if (!same_number(duration.number("duration, s"), expected.duration))
    throw mismatch(duration, "over the matrix's window and the model's free vibration, " +
                                 io::format_number(expected.duration) +
                                 " s (brb frame --duration " +
                                 io::format_number(study_case.duration) + ")");
  const io::JsonValue step = root.at("dt", "the analysis time step, s");
  if (!same_number(step.number("time step, s"), expected.dt))
    throw mismatch(step, "at the setting's step, " + io::format_number(expected.dt) +
                             " s (brb frame --step)");

  // "core_elements": a number when the run overrode the brace files' count (brb frame
  // --core-elements); null or absent (runs written before the field) when it did not
  const std::optional<io::JsonValue> elements = root.find("core_elements");
  const bool overridden = elements && !elements->json().is_null();
  const std::optional<int> run_elements =
      overridden ? std::optional<int>(static_cast<int>(elements->number("core element count")))
                 : expected.file_core_elements;
  const std::optional<int> setting_elements =
      setting.core_elements ? setting.core_elements : expected.file_core_elements;
  if (!run_elements || run_elements != setting_elements) {
    const std::string requirement =
        "with every brace of the setting's core element count, " +
        (setting_elements ? std::to_string(*setting_elements) : std::string("its file's")) +
        " (brb frame --core-elements; none or null: the brace files', " +
        (expected.file_core_elements ? std::to_string(*expected.file_core_elements)
                                     : std::string("not all the same")) +
        ")";
    if (elements)
      throw mismatch(*elements, requirement);
    throw root.error("the committed run of setting \"" + setting.label + "\" must be " +
                     requirement + " (it gives no core_elements: the brace files')");
  }

  CommittedFrameRun run;
  run.file = summary_file;
  const io::JsonValue braces = root.at("braces", "the run's braces");
  const std::size_t count = braces.expect_array(100000, "the run's braces");
  for (std::size_t b = 0; b < count; ++b) {
    const io::JsonValue brace = braces.element(b);
    const io::JsonValue fidelity = brace.at("fidelity", "truss or full");
    const std::string built = fidelity.string("brace fidelity");
    if (setting.fidelity != SettingFidelity::automatic && built != to_string(setting.fidelity))
      throw mismatch(fidelity, "with every brace " + to_string(setting.fidelity) +
                                   " (brb frame --braces " + to_string(setting.fidelity) + ")");
    (built == "truss" ? run.response.truss_braces : run.response.full_braces) += 1;
    run.response.cid.push_back(brace.at("cid", "cumulative inelastic deformation, dy")
                                   .number("cumulative inelastic deformation, dy"));
  }
  run.built_as = std::to_string(run.response.truss_braces) + " truss; " +
                 std::to_string(run.response.full_braces) + " full";
  const bool converged = boolean_of(root.at("converged", "whether every step converged"));
  const bool collapsed = boolean_of(root.at("collapse", "whether the frame collapsed"));
  run.response.completed = converged && !collapsed;
  run.response.end_time = root.at("end_time", "s").number("end time, s");
  run.response.max_drift =
      numbers_of(root.at("max_drift", "peak story drift ratios"), "peak story drift ratio");
  run.response.residual_drift = numbers_of(root.at("residual_drift", "residual story drift ratios"),
                                           "residual story drift ratio");
  const io::JsonValue stop = root.at("stop_reason", "why the run stopped");
  if (stop.json().is_string() && stop.json().get<std::string>() != "completed")
    run.stop_reason = stop.json().get<std::string>();
  run.wall_time = root.at("wall_time", "the run's wall time, s").number("wall time, s");
  return run;
}

namespace {

CaseInputs read_inputs(const ParetoCase& study_case) {
  CaseInputs inputs;
  if (study_case.kind == CaseKind::component) {
    inputs.brace = io::read_brace(study_case.brace);
    if (study_case.solid)
      inputs.solid = read_solid_reference(*study_case.solid);
    // The protocol is checked here, with the brace's dy, so a bad one stops the study first.
    const model::BraceModel truss = model::build_brace_truss_model(inputs.brace);
    const double dy = truss.yield_deformation;
    (void)io::read_protocol(study_case.protocol, dy, dy * kDefaultMaxStepInDy);
    return inputs;
  }
  inputs.frame = io::read_frame(study_case.model);
  io::GroundMotionOptions motion_options;
  motion_options.scale = study_case.scale;
  const io::GroundMotion motion = io::load_ground_motion(study_case.motion, motion_options);
  const frame::FrameRunOptions options = frame::run_options_of(inputs.frame);
  inputs.ground.direction = options.directions.front();
  inputs.ground.dt = motion.dt;
  inputs.ground.acceleration = motion.acceleration;
  // The window: the samples at times up to `duration` (as `brb frame --duration`).
  const auto samples =
      static_cast<std::size_t>(std::floor(study_case.duration / motion.dt + 1e-9)) + 1;
  if (samples < inputs.ground.acceleration.size())
    inputs.ground.acceleration.resize(samples);
  return inputs;
}

/// Costly settings first, so that the threads finish together: full before auto before
/// truss, more core elements first.
std::vector<std::size_t> run_order(const std::vector<ParetoSetting>& settings) {
  std::vector<std::size_t> order(settings.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    order[k] = k;
  const auto rank = [](SettingFidelity f) {
    return f == SettingFidelity::full ? 0 : (f == SettingFidelity::automatic ? 1 : 2);
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const ParetoSetting& sa = settings[a];
    const ParetoSetting& sb = settings[b];
    if (rank(sa.fidelity) != rank(sb.fidelity))
      return rank(sa.fidelity) < rank(sb.fidelity);
    return sa.core_elements.value_or(0) > sb.core_elements.value_or(0);
  });
  return order;
}

std::string seconds(double value) {
  std::ostringstream text;
  text.precision(4);
  text << value << " s";
  return text.str();
}

} // namespace

double median(std::vector<double> values) {
  if (values.empty())
    return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

std::vector<CaseOutcome> run_pareto_cases(const std::vector<ParetoCase>& cases,
                                          const ParetoRunOptions& options) {
  // Every input first: a bad file stops the study before its first run.
  std::vector<CaseInputs> inputs;
  for (const ParetoCase& study_case : cases)
    inputs.push_back(read_inputs(study_case));
  // Committed runs are read now too: a run that does not match its setting stops the study.
  const auto read_from_file = [&](std::size_t c, std::size_t k) {
    return cases[c].settings[k].committed_run && !options.run_committed;
  };
  std::vector<std::map<std::size_t, CommittedFrameRun>> committed(cases.size());
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (std::size_t k = 0; k < cases[c].settings.size(); ++k) {
      if (!read_from_file(c, k))
        continue;
      const ParetoSetting& setting = cases[c].settings[k];
      FrameRunExpectation expected;
      expected.dt = setting.dt.value_or(analysis_step(inputs[c]));
      expected.duration = cases[c].duration + frame::run_options_of(inputs[c].frame).free_vibration;
      expected.file_core_elements = file_core_elements(inputs[c].frame);
      committed[c].emplace(
          k, read_committed_frame_run(*setting.committed_run, cases[c], setting, expected));
    }
  }
  std::vector<CaseOutcome> outcomes(cases.size());
  // One pool of runs over all cases, costly ones first: frames' full settings before the
  // components', so that the threads finish together.
  struct Job {
    std::size_t study_case;
    std::size_t setting;
    int repeat;
  };
  std::vector<Job> jobs;
  for (const CaseKind kind : {CaseKind::frame, CaseKind::component}) {
    for (std::size_t c = 0; c < cases.size(); ++c) {
      if (cases[c].kind != kind)
        continue;
      for (const std::size_t k : run_order(cases[c].settings)) {
        if (cases[c].settings[k].fidelity != SettingFidelity::full || read_from_file(c, k))
          continue;
        const int repeats =
            options.repeats.value_or(cases[c].settings[k].repeats.value_or(cases[c].repeats));
        for (int r = 0; r < repeats; ++r)
          jobs.push_back({c, k, r});
      }
    }
  }
  for (std::size_t c = 0; c < cases.size(); ++c) {
    for (const std::size_t k : run_order(cases[c].settings)) {
      if (cases[c].settings[k].fidelity == SettingFidelity::full || read_from_file(c, k))
        continue;
      const int repeats =
          options.repeats.value_or(cases[c].settings[k].repeats.value_or(cases[c].repeats));
      for (int r = 0; r < repeats; ++r)
        jobs.push_back({c, k, r});
    }
  }
  std::vector<std::vector<std::vector<double>>> times(cases.size());
  std::vector<std::vector<std::optional<RunResult>>> first_runs(cases.size());
  std::vector<std::vector<std::string>> failures(cases.size());
  for (std::size_t c = 0; c < cases.size(); ++c) {
    times[c].resize(cases[c].settings.size());
    first_runs[c].resize(cases[c].settings.size());
    failures[c].resize(cases[c].settings.size());
    for (const auto& [k, run] : committed[c]) {
      RunResult result;
      result.wall_time = run.wall_time;
      result.built_as = run.built_as;
      result.frame = run.response;
      result.stop_reason = run.stop_reason;
      times[c][k].push_back(run.wall_time);
      first_runs[c][k] = std::move(result);
    }
  }
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  const auto work = [&]() {
    for (std::size_t j = next++; j < jobs.size(); j = next++) {
      const Job job = jobs[j];
      const ParetoCase& study_case = cases[job.study_case];
      const ParetoSetting& setting = study_case.settings[job.setting];
      std::optional<RunResult> run;
      std::string failure;
      try {
        run = study_case.kind == CaseKind::component
                  ? run_component(study_case, inputs[job.study_case], setting)
                  : run_frame(study_case, inputs[job.study_case], setting);
      } catch (const std::exception& error) {
        failure = error.what();
      }
      const std::lock_guard<std::mutex> guard(lock);
      auto& setting_times = times[job.study_case][job.setting];
      if (run) {
        setting_times.push_back(run->wall_time);
        if (!first_runs[job.study_case][job.setting])
          first_runs[job.study_case][job.setting] = std::move(run);
      } else if (failures[job.study_case][job.setting].empty()) {
        failures[job.study_case][job.setting] = failure;
      }
      if (options.progress) {
        options.progress(study_case.name + ": " + setting.label + " run " +
                         std::to_string(job.repeat + 1) + ": " +
                         (failure.empty() ? seconds(setting_times.back()) : "failed: " + failure));
      }
    }
  };
  const int threads = std::max(1, std::min<int>(options.jobs, static_cast<int>(jobs.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
    pool.emplace_back(work);
  work();
  for (std::thread& thread : pool)
    thread.join();

  for (std::size_t c = 0; c < cases.size(); ++c) {
    const ParetoCase& study_case = cases[c];
    CaseOutcome& outcome = outcomes[c];
    outcome.study_case = study_case;
    outcome.solid = inputs[c].solid;
    if (study_case.kind == CaseKind::frame) {
      std::ostringstream window;
      window << "the first " << study_case.duration << " s of "
             << study_case.motion.filename().string() << " x " << study_case.scale;
      outcome.window = window.str();
    } else {
      outcome.window = study_case.protocol.filename().string();
    }
    for (std::size_t k = 0; k < study_case.settings.size(); ++k) {
      SettingOutcome setting;
      setting.setting = study_case.settings[k];
      setting.failure = failures[c][k];
      setting.ran = failures[c][k].empty() && first_runs[c][k].has_value();
      setting.committed = committed[c].count(k) > 0;
      setting.wall_times = times[c][k];
      setting.median_time = median(times[c][k]);
      if (first_runs[c][k]) {
        const RunResult& run = *first_runs[c][k];
        setting.built_as = run.built_as;
        setting.auto_reason = run.auto_reason;
        setting.component = run.component;
        setting.frame = run.frame;
        setting.stop_reason = run.stop_reason;
        if (k == study_case.reference)
          outcome.yield_deformation = run.yield_deformation;
      }
      outcome.settings.push_back(std::move(setting));
    }
    evaluate_case(outcome);
  }
  return outcomes;
}

CaseOutcome run_pareto_case(const ParetoCase& study_case, const ParetoRunOptions& options) {
  return run_pareto_cases({study_case}, options).front();
}

void evaluate_case(CaseOutcome& outcome) {
  const ParetoCase& study_case = outcome.study_case;
  const SettingOutcome& reference = outcome.settings.at(study_case.reference);
  const bool reference_usable =
      reference.ran && (study_case.kind == CaseKind::component ? reference.component.completed
                                                               : reference.frame.completed);
  std::vector<TimeErrorPoint> primary, worst;
  for (SettingOutcome& setting : outcome.settings) {
    setting.errors = ParetoErrors{};
    if (setting.ran && reference_usable) {
      setting.errors = study_case.kind == CaseKind::component
                           ? component_errors(reference.component, setting.component)
                           : frame_errors(reference.frame, setting.frame);
    }
    if (setting.ran && outcome.solid)
      setting.errors.solid = solid_cycle_energy_error(outcome.solid->response, setting.component);
    const double time = setting.ran ? setting.median_time : std::nan("");
    primary.push_back({time, setting.errors.primary()});
    worst.push_back({time, setting.errors.worst()});
  }
  const std::vector<bool> front_primary = pareto_front(primary);
  const std::vector<bool> front_worst = pareto_front(worst);
  for (std::size_t k = 0; k < outcome.settings.size(); ++k) {
    outcome.settings[k].front_primary = front_primary[k];
    outcome.settings[k].front_worst = front_worst[k];
  }
}

} // namespace brb::study
