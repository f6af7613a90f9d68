#include "validate_command.hpp"

#include "checked_option.hpp"
#include "checkpoint_option.hpp"
#include "progress_line.hpp"

#include "brb/io/atomic_file.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/input_error.hpp"
#include "brb/validation/contrast.hpp"
#include "brb/validation/report.hpp"
#include "brb/validation/specimen.hpp"
#include "brb/validation/specimen_run.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <iomanip>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>

#ifndef BRB_DEFAULT_SHARED_DIR
#error "BRB_DEFAULT_SHARED_DIR (the shared data directory) must be defined by the build"
#endif

namespace brb::cli {
namespace {

using io::significant;

namespace fs = std::filesystem;
using namespace brb::validation;

constexpr int kAllPassed = 0;
constexpr int kSomeFailed = 1;

constexpr const char* kReportFile = "REPORT.md";
constexpr const char* kReportJsonFile = "report.json";

/// Where a specimen's runs keep their hysteresis.csv and summary.json.
fs::path run_directory(const Specimen& specimen, int refinement) {
  return specimen.directory / "out" / ("x" + std::to_string(refinement));
}

std::string joined(const std::vector<std::string>& names, const std::string& separator = ", ") {
  std::string text;
  for (const std::string& name : names)
    text += (text.empty() ? "" : separator) + name;
  return text;
}

/// The specimens to run: all, or those of --only (each must exist).
std::vector<Specimen> selected(const std::vector<Specimen>& all, const ValidateCommand& command) {
  if (command.only.empty())
    return all;
  std::vector<std::string> known;
  for (const Specimen& specimen : all)
    known.push_back(specimen.id);
  std::vector<Specimen> chosen;
  for (const std::string& id : command.only) {
    const auto found =
        std::find_if(all.begin(), all.end(), [&](const Specimen& s) { return s.id == id; });
    if (found == all.end()) {
      throw io::InputError("--only", "",
                           "no specimen \"" + id + "\" under " + command.directory.string() +
                               " (specimens: " + joined(known) + ")");
    }
    if (std::none_of(chosen.begin(), chosen.end(), [&](const Specimen& s) { return s.id == id; }))
      chosen.push_back(*found);
  }
  return chosen;
}

void check_report_directory(const fs::path& report) {
  const fs::path parent = report.parent_path();
  if (!parent.empty() && !fs::is_directory(parent)) {
    throw io::InputError(report.string(), "",
                         "--report: the directory '" + parent.string() + "' does not exist");
  }
  if (fs::is_directory(report))
    throw io::InputError(report.string(), "", "--report must name a file, and this is a directory");
}

std::string seconds(double value) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(1) << value << " s";
  return text.str();
}

void print_run(std::ostream& out, const RunOutcome& run) {
  int passed = 0;
  int failed = 0;
  for (const CheckResult& check : run.checks) {
    passed += check.status == CheckStatus::pass ? 1 : 0;
    failed += check.status == CheckStatus::fail ? 1 : 0;
  }
  out << (run.completed ? "completed" : "STOPPED EARLY") << ", " << run.steps << "/"
      << run.planned_steps << " steps"
      << (run.resumed_from_step > 0 ? " (taken up from a checkpoint at step " +
                                          std::to_string(run.resumed_from_step) + ")"
                                    : std::string())
      << ", " << seconds(run.run_seconds) << ", energy-balance error "
      << significant(run.energy_balance_error, 3) << "; " << passed << " passed, " << failed
      << " failed\n";
  for (const CheckResult& check : run.checks) {
    if (check.status == CheckStatus::fail)
      out << "    FAIL " << check.name << (check.note.empty() ? "" : ": " + check.note) << "\n";
  }
}

/// The command line that makes the same report (for its header).
std::string invocation(const ValidateCommand& command) {
  std::string text = "brb validate " + command.directory.string();
  if (!command.only.empty())
    text += " --only " + joined(command.only, ",");
  if (!command.refinements.empty()) {
    std::string list;
    for (const int refinement : command.refinements)
      list += (list.empty() ? "" : ",") + std::to_string(refinement);
    text += " --refinements " + list;
  }
  if (command.jobs != 1)
    text += " --jobs " + std::to_string(command.jobs);
  if (command.threads != 1)
    text += " --threads " + std::to_string(command.threads);
  return text;
}

/// One run to do: a specimen at a refinement.
struct Job {
  std::size_t specimen = 0;
  int refinement = 1;
};

/// Runs every job on `jobs` threads (each run has its own model: nothing is shared but the
/// read-only specimen) and returns the outcomes in job order, whatever order they finished
/// in. Progress goes to `out` as runs start and finish (and, with a `progress_interval`, as
/// their steps converge: ProgressLine). The first exception a run throws is rethrown
/// once every thread has stopped.
std::vector<RunOutcome> run_jobs(const std::vector<PreparedSpecimen>& specimens,
                                 const std::vector<Job>& jobs, std::ostream& out,
                                 const ValidateCommand& command) {
  std::vector<RunOutcome> outcomes(jobs.size());
  std::atomic<std::size_t> next{0};
  std::mutex output;
  std::exception_ptr failure;
  const auto work = [&] {
    for (std::size_t index = next++; index < jobs.size(); index = next++) {
      const Job& job = jobs[index];
      const PreparedSpecimen& specimen = specimens[job.specimen];
      std::optional<fs::path> checkpoint;
      if (command.checkpoint_directory)
        checkpoint = *command.checkpoint_directory /
                     (specimen.specimen.id + "_x" + std::to_string(job.refinement) + ".checkpoint");
      {
        const std::lock_guard lock(output);
        if (failure)
          return;
        out << specimen.specimen.id << " x" << job.refinement << ": running ("
            << specimen.brace.core_elements * job.refinement << " core elements, "
            << specimen.protocol_points - 1 << " steps"
            << (checkpoint && fs::exists(*checkpoint)
                    ? ", checkpoint " + checkpoint->string() + " found"
                    : std::string())
            << ")\n"
            << std::flush;
      }
      try {
        analysis::StepObserver progress;
        if (command.progress_interval) {
          const std::string label =
              specimen.specimen.id + " x" + std::to_string(job.refinement) + ": ";
          progress = ProgressLine(out, label, specimen.protocol_points - 1,
                                  *command.progress_interval, &output);
        }
        outcomes[index] = run_specimen(
            specimen, job.refinement, run_directory(specimen.specimen, job.refinement),
            std::move(progress), checkpoint, command.checkpoint_interval, command.threads);
        const std::lock_guard lock(output);
        out << specimen.specimen.id << " x" << job.refinement << ": ";
        print_run(out, outcomes[index]);
        out << std::flush;
      } catch (...) {
        const std::lock_guard lock(output);
        if (!failure)
          failure = std::current_exception();
        return;
      }
    }
  };
  std::vector<std::thread> workers;
  const std::size_t count =
      std::min<std::size_t>(static_cast<std::size_t>(command.jobs), jobs.size());
  for (std::size_t i = 1; i < count; ++i)
    workers.emplace_back(work);
  work();
  for (std::thread& worker : workers)
    worker.join();
  if (failure)
    std::rethrow_exception(failure);
  return outcomes;
}

} // namespace

CLI::App* add_validate_command(CLI::App& app, ValidateCommand& command) {
  auto* validate = app.add_subcommand(
      "validate", "Run the validation specimens (one folder each under DIR, with metrics.json) "
                  "at their mesh refinements and write DIR/REPORT.md and DIR/report.json.");
  validate
      ->add_option("directory", command.directory,
                   "Validation folder: one sub-folder per specimen with brace.json, "
                   "protocol.json|csv and metrics.json (validation/README.md)")
      ->type_name("DIR")
      ->required();
  validate->add_option("--only", command.only, "Run only these specimens (ids, comma separated)")
      ->type_name("ID[,ID...]")
      ->delimiter(',');
  validate
      ->add_option_function<std::string>(
          "--refinements",
          [&command](const std::string& text) {
            try {
              command.refinements = parse_refinement_list(text);
            } catch (const std::invalid_argument& error) {
              throw CLI::ValidationError("--refinements", error.what());
            }
          },
          "Multipliers of every zone's element count to run, instead of each specimen's list "
          "(e.g. 1,2,4)")
      ->type_name("K[,K...]");
  validate
      ->add_option("--report", command.report,
                   "Where to write the Markdown report (default DIR/REPORT.md); the JSON report "
                   "goes next to it with the extension .json (default DIR/report.json)")
      ->type_name("FILE");
  command.shared_directory = BRB_DEFAULT_SHARED_DIR;
  validate
      ->add_option("--shared", command.shared_directory,
                   "Shared data directory that \"shared:\" paths of reference records resolve "
                   "against")
      ->type_name("DIR")
      ->default_str(BRB_DEFAULT_SHARED_DIR);
  validate
      ->add_option("--jobs", command.jobs,
                   "Runs at a time, each on its own thread (default 1); the results do not "
                   "depend on it")
      ->type_name("N")
      ->check(CLI::Range(1, 256));
  add_element_threads_option(*validate, command.threads,
                             "Threads evaluating the elements of each run (default 1); the "
                             "results do not depend on it. Worth 2 or more for one long run at "
                             "2x or 4x (e.g. a lab record at --refinements 4); keep --jobs x "
                             "--threads within the cores");
  add_progress_option(*validate, command.progress_interval,
                      "Print a progress line of every run (\"ID xK: step k of N ...\", with "
                      "the lines of runs starting and finishing) at most every SECONDS of wall "
                      "time (0: after every step) and after its last step");
  validate
      ->add_option("--checkpoint-dir", command.checkpoint_directory,
                   "Keep a checkpoint of every run in DIR (<id>_x<k>.checkpoint, created if "
                   "missing): written after a converged step at most every --checkpoint-every "
                   "seconds; a run that finds its file (written for the same specimen files "
                   "and refinement) takes up from its step, to the same results; removed once "
                   "the run's outputs are written")
      ->type_name("DIR");
  add_checkpoint_interval_option(*validate, command.checkpoint_interval);
  validate->footer(
      "Every run keeps its hysteresis.csv and summary.json in DIR/<id>/out/x<k>/.\n"
      "Exit status: 0 every check passed, 1 a check failed (or a run failed), 2 invalid input "
      "or usage (nothing is run).");
  return validate;
}

int run_validate_command(const ValidateCommand& command, std::ostream& out) {
  // Every input is read and checked before the first run.
  std::vector<Specimen> all;
  for (const fs::path& directory : find_specimen_directories(command.directory))
    all.push_back(read_specimen(directory, command.shared_directory));
  if (all.empty()) {
    throw io::InputError(command.directory.string(), "",
                         "no specimen folder (a sub-folder holding metrics.json)");
  }
  const fs::path contrasts_file = command.directory / contrasts_file_name;
  const std::vector<ContrastSpec> contrasts = fs::exists(contrasts_file)
                                                  ? read_contrasts(contrasts_file, all)
                                                  : std::vector<ContrastSpec>{};
  std::vector<PreparedSpecimen> prepared;
  for (Specimen& specimen : selected(all, command))
    prepared.push_back(prepare_specimen(std::move(specimen)));
  const fs::path report_file = command.report.value_or(command.directory / kReportFile);
  const fs::path json_file = command.report ? fs::path(report_file).replace_extension(".json")
                                            : command.directory / kReportJsonFile;
  check_report_directory(report_file);

  std::vector<Job> jobs;
  for (std::size_t index = 0; index < prepared.size(); ++index) {
    const Specimen& specimen = prepared[index].specimen;
    for (const int refinement :
         command.refinements.empty() ? specimen.refinements : command.refinements)
      jobs.push_back(Job{index, refinement});
  }
  if (command.checkpoint_directory)
    fs::create_directories(*command.checkpoint_directory);
  std::vector<RunOutcome> outcomes = run_jobs(prepared, jobs, out, command);

  ValidationReport report;
  report.validation_directory = command.directory.string();
  report.invocation = invocation(command);
  for (std::size_t index = 0; index < prepared.size(); ++index) {
    const PreparedSpecimen& specimen = prepared[index];
    SpecimenOutcome outcome{
        specimen.specimen, specimen.yield_deformation, specimen.yield_force, {}};
    for (std::size_t job = 0; job < jobs.size(); ++job) {
      if (jobs[job].specimen == index)
        outcome.runs.push_back(std::move(outcomes[job]));
    }
    report.specimens.push_back(std::move(outcome));
  }
  report.contrasts = evaluate_contrasts(contrasts, report.specimens);
  for (const ContrastResult& contrast : report.contrasts) {
    if (contrast.status == CheckStatus::fail)
      out << "  FAIL contrast " << contrast.contrast.name << "\n";
  }

  io::write_file_atomically(report_file, report_markdown(report));
  io::write_file_atomically(json_file, report_json(report).dump(2) + "\n");
  const Tally counts = tally(report);
  out << "brb validate: " << counts.passed << " checks passed, " << counts.failed << " failed, "
      << counts.reported << " reported\n"
      << "  wrote " << report_file.string() << "\n"
      << "        " << json_file.string() << "\n";
  return counts.all_passed() ? kAllPassed : kSomeFailed;
}

} // namespace brb::cli
