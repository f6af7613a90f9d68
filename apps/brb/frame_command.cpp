#include "frame_command.hpp"

#include "output_directory.hpp"

#include "brb/frame/frame_builder.hpp"
#include "brb/frame/frame_output.hpp"
#include "brb/frame/frame_run.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/ground_motion.hpp"
#include "brb/io/input_error.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <variant>

namespace brb::cli {

namespace fs = std::filesystem;

namespace {

constexpr int kCompleted = 0;
constexpr int kStoppedEarly = 1;

io::GroundMotion read_motion(const fs::path& file, const FrameCommand& command) {
  io::GroundMotionOptions options;
  if (command.units)
    options.units = io::parse_acceleration_units(*command.units, "command line", "--units");
  options.dt = command.record_dt;
  options.scale = command.scale;
  return io::load_ground_motion(file, options);
}

analysis::GroundAcceleration component_of(const io::GroundMotion& motion,
                                          const Eigen::Vector3d& direction,
                                          std::optional<double> duration) {
  analysis::GroundAcceleration component;
  component.direction = direction;
  component.dt = motion.dt;
  component.acceleration = motion.acceleration;
  if (duration) {
    const auto samples = static_cast<std::size_t>(std::floor(*duration / motion.dt + 1e-9)) + 1;
    if (samples < component.acceleration.size())
      component.acceleration.resize(samples);
  }
  return component;
}

std::string integrator_name(frame::Integrator integrator) {
  switch (integrator) {
  case frame::Integrator::newmark:
    return "newmark";
  case frame::Integrator::hht:
    return "hht";
  case frame::Integrator::explicit_central_difference:
    return "explicit";
  }
  return "";
}

} // namespace

std::string progress_line(const frame::FrameProgress& progress, double elapsed) {
  std::ostringstream line;
  line << std::fixed << std::setprecision(3) << "brb frame: t = " << progress.time << " of "
       << progress.duration << " s (step " << progress.step << " of " << progress.steps
       << "), peak drift " << std::setprecision(2) << 100.0 * progress.peak_drift << " %, "
       << std::setprecision(1) << elapsed / 60.0 << " min so far";
  // the rest at the mean rate so far: a rough guide (the steps where braces yield cost more)
  if (progress.step > 0 && progress.steps > progress.step) {
    const double left = elapsed / static_cast<double>(progress.step) *
                        static_cast<double>(progress.steps - progress.step);
    line << ", about " << left / 60.0 << " min left";
  }
  return line.str();
}

CLI::App* add_frame_command(CLI::App& app, FrameCommand& command) {
  auto* frame = app.add_subcommand(
      "frame", "Nonlinear time-history analysis of a frame model under a ground motion: "
               "gravity, modal analysis, then the record step by step.");
  frame
      ->add_option("model", command.model, "Frame model file, JSON (README: \"Frame model files\")")
      ->type_name("MODEL.json")
      ->required();
  frame
      ->add_option("--motion", command.motion,
                   "Ground acceleration along the model's first ground direction: PEER .AT2, "
                   ".csv (time,accel or one column with --dt) or a one-column .rec/.txt")
      ->type_name("FILE")
      ->required();
  frame
      ->add_option("--motion2", command.motion_2,
                   "Component along the model's second ground-motion direction "
                   "(ground_motion.directions, e.g. \"y\" or the vertical \"z\")")
      ->type_name("FILE");
  frame
      ->add_option("--motion3", command.motion_3,
                   "Component along the model's third ground-motion direction")
      ->type_name("FILE");
  frame->add_option("--scale", command.scale, "Scale factor on the record(s); default 1")
      ->type_name("S");
  frame
      ->add_option("--units", command.units,
                   "Units of the record: g, m/s^2 or mm/s^2 (AT2 files state theirs)")
      ->type_name("UNITS");
  frame->add_option("--dt", command.record_dt, "Time step of a one-column record, s")
      ->type_name("S");
  frame
      ->add_option("--duration", command.duration, "Analyse only the first S seconds of the record")
      ->type_name("S");
  frame
      ->add_option("--step", command.step,
                   "Analysis time step, s, instead of the model's analysis.dt (default: that, "
                   "or the record's step when the model gives none)")
      ->type_name("S");
  frame
      ->add_option("--core-elements", command.core_elements,
                   "Core elements of every brace instead of its brace file's count (the contact "
                   "links follow the core stations); for full braces")
      ->type_name("N");
  frame
      ->add_option("--progress", command.progress_interval,
                   "Seconds of run time between progress lines on stderr (time reached, steps, "
                   "peak drift, time left); default 30, 0: none")
      ->type_name("S");
  frame
      ->add_option("--braces", command.braces,
                   "Build every brace as: elastic (an elastic truss of its axial stiffness), "
                   "truss, full or auto, instead of the fidelity the model file gives")
      ->type_name("FIDELITY");
  frame
      ->add_option("--out", command.output_directory,
                   "Output directory (created if missing; its parent must exist)")
      ->type_name("DIR")
      ->required();
  frame->footer("Outputs (README, \"brb frame\"): summary.json and the histories the model's\n"
                "recorders ask for: drifts.csv, floor_accelerations.csv, base_shear.csv,\n"
                "energy.csv, braces.csv. Units: N, mm, s; accelerations in g.\n"
                "Exit status: 0 completed (or collapse detected), 1 a step failed after every\n"
                "fallback (what was computed is written), 2 invalid input (nothing written).");
  return frame;
}

int run_frame_command(const FrameCommand& command, std::ostream& report, std::ostream& notes) {
  const auto started = std::chrono::steady_clock::now();
  // Every input is read and checked before anything is written.
  model::FrameSpec spec = io::read_frame(command.model);
  if (!(std::isfinite(command.scale) && command.scale != 0.0))
    throw io::InputError("command line", "--scale", "must be a finite number other than 0");
  if (command.duration && !(*command.duration > 0.0))
    throw io::InputError("command line", "--duration", "must be > 0 s");
  if (!(std::isfinite(command.progress_interval) && command.progress_interval >= 0.0))
    throw io::InputError("command line", "--progress", "must be a finite number of seconds >= 0");
  if (command.step && !(std::isfinite(*command.step) && *command.step > 0.0))
    throw io::InputError("command line", "--step", "must be a finite time step > 0 s");
  if (command.core_elements && !(*command.core_elements >= 1 && *command.core_elements <= 4096))
    throw io::InputError("command line", "--core-elements",
                         "must be a whole number from 1 to 4096");
  if (command.core_elements)
    spec.set_brace_core_elements(*command.core_elements);
  frame::FrameRunOptions options = frame::run_options_of(spec);
  if (command.step)
    options.dt = *command.step;
  std::vector<analysis::GroundAcceleration> components;
  const io::GroundMotion motion = read_motion(command.motion, command);
  components.push_back(component_of(motion, options.directions.front(), command.duration));
  const std::array<const std::optional<fs::path>*, 2> more{&command.motion_2, &command.motion_3};
  for (std::size_t k = 0; k < more.size(); ++k) {
    if (!*more[k])
      continue;
    const std::string option = k == 0 ? "--motion2" : "--motion3";
    if (options.directions.size() < k + 2 || components.size() != k + 1)
      throw io::InputError(command.model.string(), "/ground_motion/directions",
                           option + " needs the model to list " + std::to_string(k + 2) +
                               " directions (and the components before it given)");
    components.push_back(
        component_of(read_motion(**more[k], command), options.directions[k + 1], command.duration));
  }
  options.directions.resize(components.size());
  if (!(options.dt > 0.0))
    options.dt = motion.dt;
  frame::BraceOverride braces = frame::BraceOverride::none;
  if (command.braces) {
    const auto named = frame::brace_override_named(*command.braces);
    if (!named)
      throw io::InputError("command line", "--braces",
                           "must be elastic, truss, full or auto (got \"" + *command.braces +
                               "\")");
    braces = *named;
  }
  check_output_directory(command.output_directory);
  frame::FrameModel frame = frame::build_frame(spec, command.model.string(), braces);
  if (braces == frame::BraceOverride::elastic)
    options.recorders.braces.clear();
  if (spec.recorders.all_braces) {
    for (const frame::BraceReference& brace : frame.braces)
      options.recorders.braces.push_back(brace.id);
  }

  // A run with full braces can take an hour: say where it stands every progress_interval.
  auto next_report = started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                   std::chrono::duration<double>(command.progress_interval));
  if (command.progress_interval > 0.0) {
    options.progress = [&](const frame::FrameProgress& progress) {
      const auto now = std::chrono::steady_clock::now();
      if (now < next_report)
        return;
      next_report = now + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                              std::chrono::duration<double>(command.progress_interval));
      const double elapsed = std::chrono::duration<double>(now - started).count();
      notes << progress_line(progress, elapsed) << std::endl;
    };
  }
  const frame::FrameRunResult result = frame::run_time_history(frame, components, options);

  frame::FrameRunDescription description;
  description.model_file = command.model.string();
  description.motion_file = command.motion.string();
  description.scale = command.scale;
  description.integrator = integrator_name(options.integrator);
  description.dt = options.dt;
  description.core_elements = command.core_elements;
  description.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fs::create_directory(command.output_directory);
  frame::write_frame_outputs(command.output_directory, frame, result, description);

  report << "brb frame: " << (frame.title.empty() ? command.model.string() : frame.title)
         << " under " << command.motion.filename().string() << " x " << command.scale << "\n";
  if (!result.periods.empty())
    report << "  T1 = " << std::setprecision(4) << result.periods.front() << " s\n";
  report << "  " << (result.stop_reason == "completed" ? "completed" : "stopped")
         << " at t = " << result.end_time << " of " << result.duration << " s (" << result.steps
         << " steps, " << result.fallbacks.size() << " fallbacks)";
  if (result.stop_reason != "completed")
    report << ": " << result.stop_reason;
  report << "\n";
  // (no drifts when the gravity load failed: the run stopped before any step)
  for (std::size_t s = 0; s < result.max_drift.size(); ++s) {
    report << "  story " << frame.stories[s].name << ": peak drift " << std::setprecision(4)
           << 100.0 * result.max_drift[s] << " %, residual " << 100.0 * result.residual_drift[s]
           << " %\n";
  }
  report << "  energy balance error " << std::setprecision(3) << result.energy_balance_error
         << " of the input energy\n";
  for (const frame::BraceReference& brace : frame.braces) {
    if (!brace.fidelity_reason.empty()) {
      report << "  brace " << brace.id << ": " << brace.fidelity_reason << "\n";
      break; // one line is enough to say how `auto` decided; summary.json has each brace
    }
  }
  report << "  outputs: " << (command.output_directory / "summary.json").string() << "\n";
  if (!result.gravity_converged || (!result.converged && !result.collapsed)) {
    notes << "brb: error: " << command.model.string() << ": " << result.stop_reason << "\n";
    return kStoppedEarly;
  }
  return kCompleted;
}

} // namespace brb::cli
