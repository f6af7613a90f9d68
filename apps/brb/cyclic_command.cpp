#include "cyclic_command.hpp"

#include "checked_option.hpp"
#include "checkpoint_option.hpp"
#include "output_directory.hpp"
#include "progress_line.hpp"

#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/atomic_file.hpp"
#include "brb/io/brace_input.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/cyclic_output.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"
#include "brb/io/material_input.hpp"
#include "brb/io/protocol.hpp"
#include "brb/material/parameter_error.hpp"
#include "brb/model/brace_model.hpp"
#include "brb/model/brace_spec.hpp"

#include <cstddef>
#include <filesystem>
#include <iomanip>
#include <ios>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace brb::cli {
namespace {

using io::significant;

namespace fs = std::filesystem;

constexpr int kCompleted = 0;
constexpr int kStoppedEarly = 1;

/// Without --max-step, a protocol that gives no max_step is followed in steps of dy / 10.
constexpr double kDefaultStepsPerYieldDeformation = 10.0;

constexpr const char* kHysteresisFile = "hysteresis.csv";
constexpr const char* kSummaryFile = "summary.json";
constexpr const char* kElementHistoryFile = "element_history.csv";
constexpr const char* kShapeFile = "shape.csv";

/// The text summary lists at most this many cycles (the first and the last half of them);
/// summary.json has them all.
constexpr std::size_t kMostCyclesListed = 12;

using io::converged_steps;

/// "1 cycle", "3 cycles".
std::string count_of(std::size_t count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string count_of(int count, const std::string& noun) {
  return count_of(static_cast<std::size_t>(count < 0 ? 0 : count), noun);
}

/// `value` with `decimals` digits after the point.
std::string with_decimals(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

void print_cycle_table(std::ostream& out, const std::vector<analysis::CycleMetrics>& cycles,
                       double yield_deformation) {
  out << "  cycle  amplitude (mm)  amplitude (dy)   energy (N mm)  max tension (N)"
         "  max compression (N)\n";
  const auto print_row = [&](const analysis::CycleMetrics& cycle) {
    out << std::setw(7) << cycle.index << std::setw(16) << significant(cycle.amplitude, 6)
        << std::setw(16) << with_decimals(cycle.amplitude / yield_deformation, 3) << std::setw(16)
        << significant(cycle.energy, 6) << std::setw(17) << significant(cycle.max_tension, 6)
        << std::setw(21) << significant(cycle.max_compression, 6) << "\n";
  };
  const std::size_t listed_each_end = kMostCyclesListed / 2;
  for (std::size_t index = 0; index < cycles.size(); ++index) {
    const bool elided = cycles.size() > kMostCyclesListed && index >= listed_each_end &&
                        index < cycles.size() - listed_each_end;
    if (!elided) {
      print_row(cycles[index]);
    } else if (index == listed_each_end) {
      out << "    ... " << cycles.size() - 2 * listed_each_end
          << " more cycles in summary.json ...\n";
    }
  }
}

struct OutputFiles {
  fs::path hysteresis;
  fs::path summary;
  std::optional<fs::path> element_history;
  std::optional<fs::path> shape;
};

void print_report(std::ostream& out, const CyclicCommand& command, const std::string& name,
                  const model::BraceModel& brace, const io::LoadingProtocol& protocol,
                  const analysis::CyclicTestResult& result, const OutputFiles& files) {
  const double dy = brace.yield_deformation;
  const std::size_t planned_steps = protocol.deformation.size() - 1;
  out << "brb cyclic: brace " << name << " (" << command.brace.string() << ")\n"
      << "  yield deformation dy = " << significant(dy, 6)
      << " mm, yield force Py = " << significant(brace.yield_force, 6) << " N\n"
      << "  protocol " << protocol.name << ": " << count_of(protocol.cycle_count(), "cycle") << ", "
      << count_of(planned_steps, "step") << "\n\n";
  if (result.cycles.empty()) {
    out << "  no cycle was completed\n";
  } else {
    print_cycle_table(out, result.cycles, dy);
  }
  out << "\n";
  if (result.completed) {
    out << "  completed: all " << planned_steps << " steps\n";
  } else {
    out << "  stopped early after " << converged_steps(result) << " of " << planned_steps
        << " steps: " << result.stop_reason << "\n";
  }
  out << "  peak forces: tension " << significant(result.max_tension, 6) << " N, compression "
      << significant(result.max_compression, 6) << " N; work of the force over the history "
      << significant(result.energy_total, 6) << " N mm\n"
      << "  solver: " << count_of(converged_steps(result), "step") << ", "
      << count_of(result.iterations, "Newton iteration") << ", "
      << count_of(result.substeps, "substep") << ", "
      << count_of(result.regularised_steps, "regularised step") << ", "
      << count_of(result.unstable_accepted, "unstable substep") << " accepted, "
      << count_of(result.far_branch_cuts, "far-branch cut") << "\n";
  const analysis::EnergyBalance& balance = result.energy_balance;
  out << "  energy balance: external work " << significant(balance.external_work, 6)
      << " N mm, stored " << significant(balance.stored, 6) << ", dissipated "
      << significant(balance.dissipated, 6) << ", integration misfit "
      << significant(balance.integration_misfit, 3) << ", released in jumps "
      << significant(balance.released_in_jumps, 6) << ", relative error "
      << significant(balance.relative_error(), 3) << " (laws' balance "
      << significant(balance.law_relative_error(), 3) << ")\n"
      << "  wrote " << files.hysteresis.string() << "\n"
      << "        " << files.summary.string() << "\n";
  if (files.element_history)
    out << "        " << files.element_history->string() << "\n";
  if (files.shape)
    out << "        " << files.shape->string() << "\n";
}

/// A solver control's tolerance: a fraction of the gross work in [0, 1) (0: the control off).
void add_fraction_option(CLI::App& command, const std::string& name, double& fraction,
                         const std::string& description) {
  add_checked_number_option(
      command, name, fraction, [](double value) { return value >= 0.0 && value < 1.0; },
      "must be a number in [0, 1)", "FRACTION", description);
}

} // namespace

/// The brace's name in the outputs: its "name", or the brace file's name without extension.
std::string brace_name(const model::BraceSpec& spec, const std::filesystem::path& file) {
  return spec.name.empty() ? file.stem().string() : spec.name;
}

/// The brace's finite element model: the expanded full model, or the truss for
/// "element": {"fidelity": "truss"} (the element mode only matters in frames). A ParameterError
/// (inconsistent geometry, named by its key in the brace schema, e.g. "core/yielding_length")
/// becomes an InputError at that JSON path of `file` ("/core/yielding_length"), with the value
/// found there.
model::BraceModel build_brace(const model::BraceSpec& spec, const std::filesystem::path& file) {
  try {
    return spec.element.fidelity == model::Fidelity::truss ? model::build_brace_truss_model(spec)
                                                           : model::build_brace_model(spec);
  } catch (const ParameterError& error) {
    throw io::input_error_from(error, io::ParameterSource{file.string(), io::read_json_file(file)});
  }
}

void add_max_step_option(CLI::App& command, std::optional<double>& max_step,
                         const std::string& description) {
  add_checked_number_option(
      command, "--max-step", max_step, [](double value) { return value > 0.0; },
      "must be a finite number of mm > 0", "MM", description);
}

CLI::App* add_cyclic_command(CLI::App& app, CyclicCommand& command) {
  auto* cyclic = app.add_subcommand(
      "cyclic", "Virtual cyclic test: drive a brace's axial deformation through a loading "
                "protocol and write its hysteresis and a summary.");
  cyclic
      ->add_option("brace", command.brace,
                   "Brace file, JSON (comments allowed); schema in the README, \"Brace files\"")
      ->type_name("BRACE.json")
      ->required();
  cyclic
      ->add_option("--protocol", command.protocol,
                   "Loading protocol: a protocol file (.json: cycles in mm or dy, or a built-in "
                   "girona / ucsd) or a deformation history (.csv, column 'deformation', mm)")
      ->type_name("P.json|P.csv")
      ->required();
  cyclic
      ->add_option("--out", command.output_directory,
                   "Output directory (created if missing; its parent must exist): "
                   "hysteresis.csv and summary.json")
      ->type_name("DIR")
      ->required();
  add_max_step_option(*cyclic, command.max_step,
                      "Largest change of deformation per step, mm, when the protocol gives no "
                      "max_step (always for .csv histories); default dy / 10");
  add_fraction_option(*cyclic, "--energy-tolerance", command.energy_tolerance,
                      "Energy-error control: a step is cut while the running sum of |trapezoidal "
                      "work - change of stored and dissipated energy| would exceed this fraction "
                      "of the gross work; default 1e-2 (a guard against steps that jump to a far "
                      "branch), 0: off");
  add_fraction_option(*cyclic, "--balance-tolerance", command.balance_tolerance,
                      "Balance control: a step is cut while the energy balance's running error "
                      "(external work - stored - dissipated - integration misfit - released, "
                      "summary.json's relative_error) would exceed this fraction of the gross "
                      "work; default 0 (off); it can move a restrained core's path (README, "
                      "\"Energy balance\")");
  cyclic->add_flag("--histories", command.histories,
                   "Also write element_history.csv: core strain, dissipated energy, cumulative "
                   "inelastic deformation, lateral displacements, half-waves, damage and flags "
                   "after every step");
  cyclic
      ->add_option_function<std::vector<int>>(
          "--shape-steps",
          [&command](const std::vector<int>& steps) {
            for (const int step : steps) {
              if (step < 0)
                throw CLI::ValidationError("--shape-steps", "step numbers must be >= 0 (0: the "
                                                            "unloaded initial state)");
            }
            command.shape_steps = steps;
          },
          "Also write shape.csv: the deformed brace (lateral displacements of the core and "
          "casing, bearing forces, mortar damage per node) after these steps (hysteresis.csv's "
          "step numbers, comma-separated) and after the last converged step")
      ->delimiter(',')
      ->type_name("STEP,...");
  add_progress_option(*cyclic, command.progress_interval,
                      "Print a progress line on stderr at most every SECONDS of wall time (0: "
                      "after every step) and after the last step: step k of N, deformation, "
                      "force, substeps so far, elapsed time");
  cyclic
      ->add_option("--checkpoint", command.checkpoint,
                   "Checkpoint file of a long run: written after a converged step at most "
                   "every --checkpoint-every seconds; a run that finds it (written for the same "
                   "brace and protocol files and settings) takes up from its step, to the same "
                   "results; removed once the outputs are written")
      ->type_name("FILE");
  add_checkpoint_interval_option(*cyclic, command.checkpoint_interval);
  add_element_threads_option(*cyclic, command.threads,
                             "Threads evaluating the brace's elements at each Newton iteration "
                             "(default 1); the results are the same for any count. Worth 2 or "
                             "more on a long run of a finely divided core (e.g. 32 or more core "
                             "elements)");
  cyclic->footer(
      "Outputs (README, \"brb cyclic\"):\n"
      "  hysteresis.csv: step,cycle,deformation,force,max_lateral_displacement,substeps\n"
      "    (mm, N; tension and elongation positive)\n"
      "  summary.json: yield force and deformation, peak forces, energy per cycle, solver\n"
      "    statistics, energy balance, element outputs\n"
      "  element_history.csv (with --histories): the element outputs after every step\n"
      "  shape.csv (with --shape-steps): step,node,position,lateral_y,lateral_z,station,\n"
      "    casing_lateral_y,casing_lateral_z,bearing_force_y,bearing_force_z,mortar_damage,\n"
      "    friction_force,wave_normal_force,core_axial_force,core_axial_strain,\n"
      "    casing_axial_force\n"
      "Units: N, mm, MPa. Exit status: 0 completed, 1 the analysis stopped early (what was\n"
      "computed is written) or the run failed, 2 invalid input or usage (nothing written).");
  return cyclic;
}

int run_cyclic_command(const CyclicCommand& command, std::ostream& report, std::ostream& notes) {
  // Every input is read and checked before anything is written.
  const model::BraceSpec spec = io::read_brace(command.brace);
  const std::string name = brace_name(spec, command.brace);
  model::BraceModel brace = build_brace(spec, command.brace);
  const double default_max_step =
      command.max_step.value_or(brace.yield_deformation / kDefaultStepsPerYieldDeformation);
  const io::LoadingProtocol protocol =
      io::read_protocol(command.protocol, brace.yield_deformation, default_max_step);
  check_output_directory(command.output_directory);
  for (const std::string& warning : brace.warnings) {
    notes << "brb: warning: " << command.brace.string() << ": " << warning << "\n";
  }

  analysis::NewtonSettings settings;
  settings.energy_tolerance = command.energy_tolerance;
  settings.balance_tolerance = command.balance_tolerance;
  settings.element_threads = command.threads;
  analysis::StepObserver progress;
  if (command.progress_interval)
    progress = ProgressLine(notes, "brb: cyclic: ", protocol.deformation.size() - 1,
                            *command.progress_interval);
  std::optional<analysis::CyclicCheckpoint> checkpoint;
  if (command.checkpoint) {
    // the run key: the input files' bytes and every setting that moves the path
    std::ostringstream key;
    key << std::setprecision(17) << "cyclic brace " << io::file_fingerprint(command.brace)
        << " protocol " << io::file_fingerprint(command.protocol) << " max_step "
        << default_max_step << " energy_tolerance " << settings.energy_tolerance
        << " balance_tolerance " << settings.balance_tolerance << " histories " << command.histories
        << " shapes";
    for (const int step : command.shape_steps.value_or(std::vector<int>{}))
      key << " " << step;
    checkpoint =
        analysis::CyclicCheckpoint{*command.checkpoint, command.checkpoint_interval, key.str(),
                                   [&notes, &command](const analysis::ResumedRun& resumed) {
                                     notes << "brb: cyclic: taking up the run from the checkpoint "
                                           << command.checkpoint->string() << " at step "
                                           << resumed.steps << " (" << std::fixed
                                           << std::setprecision(1) << resumed.elapsed_seconds
                                           << " s of earlier runs)\n"
                                           << std::defaultfloat;
                                   }};
  }
  const analysis::CyclicTestResult result = analysis::run_cyclic_test(
      brace, protocol.deformation, protocol.cycle, protocol.cycle_amplitude, settings,
      command.histories, command.shape_steps, std::move(progress), checkpoint);

  // Written also when the analysis stopped early: what was computed is a result too.
  OutputFiles files{command.output_directory / kHysteresisFile,
                    command.output_directory / kSummaryFile, std::nullopt, std::nullopt};
  if (command.histories)
    files.element_history = command.output_directory / kElementHistoryFile;
  if (command.shape_steps)
    files.shape = command.output_directory / kShapeFile;
  fs::create_directory(command.output_directory);
  io::write_file_atomically(files.hysteresis, io::hysteresis_table(result).text());
  if (files.element_history) {
    io::write_file_atomically(*files.element_history, io::element_history_table(result).text());
  }
  if (files.shape)
    io::write_file_atomically(*files.shape, io::brace_shape_table(result).text());
  io::write_file_atomically(
      files.summary,
      io::cyclic_summary_json(name, brace.yield_deformation, brace.yield_force, result).dump(2) +
          "\n");

  if (checkpoint) // the outputs hold the whole run now
    fs::remove(checkpoint->file);

  print_report(report, command, name, brace, protocol, result, files);
  if (!result.completed) {
    notes << "brb: error: " << command.protocol.string()
          << ": the cyclic test stopped early: " << result.stop_reason
          << "; the steps computed before are in " << files.hysteresis.string() << " and "
          << files.summary.string() << "\n";
    return kStoppedEarly;
  }
  return kCompleted;
}

} // namespace brb::cli
