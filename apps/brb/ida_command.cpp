#include "ida_command.hpp"

#include "output_directory.hpp"

#include "brb/ida/ida_mpi.hpp"
#include "brb/ida/ida_output.hpp"
#include "brb/ida/ida_run.hpp"
#include "brb/io/frame_input.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <memory>
#include <thread>

namespace brb::cli {

namespace fs = std::filesystem;

namespace {

constexpr int kCompleted = 0;
constexpr int kInvalidInput = 2;

frame::BraceOverride brace_override(const std::optional<std::string>& name) {
  if (!name)
    return frame::BraceOverride::none;
  if (const auto braces = frame::brace_override_named(*name))
    return *braces;
  throw io::InputError("command line", "--braces",
                       "must be elastic, truss, full or auto (got \"" + *name + "\")");
}

void require_positive(double value, const char* option, const char* meaning) {
  if (!(std::isfinite(value) && value > 0.0))
    throw io::InputError("command line", option, std::string(meaning) + " must be > 0");
}

ida::IdaSettings settings_of(const IdaCommand& command) {
  ida::IdaSettings settings;
  if (command.measure == "sa")
    settings.measure = ida::IntensityMeasure::sa_t1;
  else if (command.measure == "pga")
    settings.measure = ida::IntensityMeasure::pga;
  else
    throw io::InputError("command line", "--im",
                         "must be sa (Sa(T1, 5 %)) or pga (got \"" + command.measure + "\")");
  if (command.period)
    require_positive(*command.period, "--period", "the period of Sa, s,");
  settings.period = command.period;
  if (!(command.damping_ratio >= 0.0 && command.damping_ratio < 1.0))
    throw io::InputError("command line", "--damping", "must be in [0, 1)");
  settings.damping_ratio = command.damping_ratio;
  require_positive(command.first, "--first", "the first intensity, g,");
  require_positive(command.step, "--step", "the hunting step, g,");
  require_positive(command.resolution, "--resolution", "the collapse resolution, g,");
  if (!(command.step_growth >= 0.0))
    throw io::InputError("command line", "--step-growth", "must be >= 0 g");
  if (command.max_runs < 1)
    throw io::InputError("command line", "--runs", "the run budget per record must be >= 1");
  if (!(command.max_intensity >= 0.0))
    throw io::InputError("command line", "--max-intensity", "must be >= 0 g (0: no limit)");
  settings.trace = {command.first,      command.step,     command.step_growth,
                    command.resolution, command.max_runs, command.max_intensity};
  if (command.drift_limit && !(*command.drift_limit > 0.0 && *command.drift_limit < 1.0))
    throw io::InputError("command line", "--drift-limit", "must be a drift ratio in (0, 1)");
  settings.drift_limit = command.drift_limit;
  if (command.mce)
    require_positive(*command.mce, "--mce", "the MCE intensity S_MT, g,");
  settings.mce_intensity = command.mce;
  settings.braces = brace_override(command.braces);
  return settings;
}

int thread_count(int asked) {
  if (asked > 0)
    return asked;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

} // namespace

CLI::App* add_ida_command(CLI::App& app, IdaCommand& command) {
  auto* ida = app.add_subcommand(
      "ida", "Incremental dynamic analysis of a frame over a ground-motion suite: hunt-and-fill "
             "tracing of each record's curve to collapse, fractiles, collapse fragility.");
  ida->add_option("model", command.model, "Frame model file, JSON (README: \"Frame model files\")")
      ->type_name("MODEL.json")
      ->required();
  ida->add_option("--suite", command.suite,
                  "Ground-motion suite file, JSON (README: \"Ground-motion suite files\")")
      ->type_name("SUITE.json")
      ->required();
  ida->add_option("--out", command.output_directory,
                  "Output directory (created if missing; its parent must exist)")
      ->type_name("DIR")
      ->required();
  ida->add_option("--jobs", command.jobs, "Threads (records run in parallel); default: every core")
      ->type_name("N");
  ida->add_flag("--resume", command.resume,
                "Continue the study whose journal is in DIR (runs it holds are not run again)");
  ida->add_option("--im", command.measure,
                  "Intensity measure: sa (Sa(T1, 5 %), default) or pga; in g")
      ->type_name("MEASURE");
  ida->add_option("--period", command.period, "Period of Sa, s; default T1 of the frame")
      ->type_name("S");
  ida->add_option("--damping", command.damping_ratio, "Damping ratio of Sa; default 0.05")
      ->type_name("ZETA");
  ida->add_option("--first", command.first, "First intensity, g; default 0.2")->type_name("IM");
  ida->add_option("--step", command.step, "First hunting step, g; default 0.2")->type_name("IM");
  ida->add_option("--step-growth", command.step_growth,
                  "Added to the step after each hunting run, g; default 0.2")
      ->type_name("IM");
  ida->add_option("--resolution", command.resolution,
                  "Width of the collapse bracket at which bisection stops, g; default 0.05")
      ->type_name("IM");
  ida->add_option("--runs", command.max_runs, "Run budget per record; default 12")->type_name("N");
  ida->add_option("--max-intensity", command.max_intensity,
                  "Hunting stops above this intensity, g; default 0 (no limit)")
      ->type_name("IM");
  ida->add_option("--drift-limit", command.drift_limit,
                  "Collapse drift ratio; default the model's analysis.drift_limit (0.10)")
      ->type_name("RATIO");
  ida->add_option("--mce", command.mce,
                  "MCE intensity S_MT, g: the FEMA P695 collapse margin ratio is reported")
      ->type_name("IM");
  ida->add_option("--braces", command.braces,
                  "Build every brace as elastic, truss, full or auto instead of the model's")
      ->type_name("FIDELITY");
  ida->add_flag("--quiet", command.quiet, "No progress lines");
  ida->footer(
      "Outputs (README, \"brb ida\"): ida_points.csv, ida_curves.csv, ida_fractiles.csv,\n"
      "collapse_fragility.csv, summary.json, and journal.jsonl (one line per finished run;\n"
      "--resume continues from it). Under mpirun with several ranks: rank 0 is the master,\n"
      "the others trace records (build with -DBRB_WITH_MPI=ON).\n"
      "Exit status: 0 done, 1 a run failed in a way that is not an analysis result, 2 input.");
  return ida;
}

int run_ida_command(const IdaCommand& command, std::ostream& report, std::ostream& notes) {
  const auto started = std::chrono::steady_clock::now();
  const bool distributed = ida::mpi::launched_with_several_ranks();
  if (distributed && !ida::mpi::available())
    throw io::InputError("command line", "mpirun",
                         "this brb was built without MPI: configure with -DBRB_WITH_MPI=ON");
  std::unique_ptr<ida::mpi::Session> session;
  if (distributed)
    session = std::make_unique<ida::mpi::Session>();
  const bool master = !session || session->rank() == 0;

  // Every input is read and checked before the first run (on every rank: the same files).
  const ida::IdaSettings settings = settings_of(command);
  if (command.jobs < 0)
    throw io::InputError("command line", "--jobs", "must be >= 1 (or 0: every core)");
  const std::string model_text = io::read_text_file(command.model);
  const std::string suite_text = io::read_text_file(command.suite);
  model::FrameSpec spec = io::read_frame(command.model);
  io::GroundMotionSuite suite = io::read_suite(command.suite);
  const ida::IdaStudy study(std::move(spec), command.model.string(), std::move(suite), settings);
  const nlohmann::json header = study.header(model_text, suite_text);

  if (session && !master) {
    if (session->broadcast_go(false))
      ida::mpi::run_worker(*session, study);
    return kCompleted;
  }

  // The master (or the only process): the journal.
  const fs::path journal_file = command.output_directory / "journal.jsonl";
  std::optional<ida::Journal> journal;
  std::vector<nlohmann::json> entries;
  try {
    check_output_directory(command.output_directory);
    if (fs::exists(journal_file) && !command.resume)
      throw io::InputError(journal_file.string(), "",
                           "an IDA journal is already here: continue it with --resume, or "
                           "choose another --out");
    fs::create_directories(command.output_directory);
    if (command.resume && fs::exists(journal_file)) {
      try {
        journal.emplace(ida::Journal::resume(journal_file, header, entries));
      } catch (const std::invalid_argument& error) {
        throw io::InputError(journal_file.string(), "", error.what());
      }
    } else {
      journal.emplace(ida::Journal::create(journal_file, header));
    }
  } catch (...) {
    if (session)
      session->broadcast_go(false);
    throw;
  }
  if (session)
    session->broadcast_go(true);
  std::vector<std::map<double, ida::IdaPoint>> known;
  try {
    known = ida::points_by_record(entries, study.record_count());
  } catch (const std::invalid_argument& error) {
    if (session)
      throw; // the workers wait for tasks: an inconsistent journal here is a failed run
    throw io::InputError(journal_file.string(), "", error.what());
  }

  const int jobs = session ? session->size() - 1 : thread_count(command.jobs);
  report << "brb ida: " << study.record_count() << " records of " << study.suite().name << ", IM "
         << study.measure_label() << " in g, "
         << (session ? std::to_string(jobs) + " MPI workers" : std::to_string(jobs) + " threads")
         << (entries.empty() ? ""
                             : ", " + std::to_string(entries.size()) + " runs from the journal")
         << "\n";
  ida::IdaProgress progress(command.quiet ? nullptr : &notes, study.record_count(),
                            settings.trace.max_runs);
  const std::vector<ida::IdaPoint> points =
      session ? ida::mpi::run_master(*session, study, *journal, known, progress)
              : ida::run_ida_threads(study, *journal, known, jobs, progress);

  ida::IdaRunDescription description;
  description.model_file = command.model.string();
  description.suite_file = command.suite.string();
  description.jobs = jobs;
  description.parallelism = session ? "mpi" : "threads";
  description.runs_this_session = points.size() - std::min(points.size(), entries.size());
  description.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const nlohmann::json summary =
      ida::write_ida_outputs(command.output_directory, study, points, description);

  std::size_t collapses = 0;
  for (const ida::IdaPoint& point : points)
    collapses += point.collapsed() ? 1 : 0;
  report << "  " << points.size() << " runs (" << collapses << " collapsed), "
         << std::setprecision(3) << description.wall_time << " s; outputs in "
         << command.output_directory.string() << "\n";
  // the headline numbers of the summary
  for (const nlohmann::json& record : summary["records"]) {
    if (!record.contains("collapse_intensity_g"))
      continue;
    report << "  " << record["name"].get<std::string>() << ": "
           << (record["censored"].get<bool>() ? "no collapse up to " : "collapse at ")
           << std::setprecision(3) << record["collapse_intensity_g"].get<double>() << " g";
    if (!record["censored"].get<bool>() && !record["bracket_resolved"].get<bool>())
      report << " (above " << record["highest_survival_g"].get<double>()
             << " g; the run budget ended the bisection)";
    report << "\n";
  }
  const nlohmann::json& fragility = summary["fragility"];
  if (fragility.is_null()) {
    report << "  " << summary.value("fragility_note", "no fragility") << "\n";
  } else {
    report << "  collapse fragility: median " << std::setprecision(3)
           << fragility["median_g"].get<double>() << " g, dispersion "
           << fragility["dispersion"].get<double>();
    if (fragility.contains("collapse_margin_ratio"))
      report << "; CMR " << fragility["collapse_margin_ratio"].get<double>() << " for S_MT "
             << fragility["mce_intensity_g"].get<double>() << " g";
    report << "\n";
  }
  return kCompleted;
}

} // namespace brb::cli
