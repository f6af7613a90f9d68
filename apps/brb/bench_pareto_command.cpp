#include "bench_pareto_command.hpp"

#include "output_directory.hpp"

#include "brb/io/input_error.hpp"
#include "brb/study/pareto_matrix.hpp"
#include "brb/study/pareto_report.hpp"
#include "brb/study/pareto_runner.hpp"

#include <algorithm>
#include <iomanip>
#include <mutex>

namespace brb::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kCompleted = 0;
constexpr int kReferenceFailed = 1;

/// Without --matrix: the committed default matrices.
std::vector<fs::path> default_matrices() {
  const fs::path folder = fs::path("bench") / "pareto";
  if (!fs::is_directory(folder))
    throw io::InputError(folder.string(), "",
                         "no --matrix given and no default matrix folder here: run from the "
                         "repository's root or name the matrix files");
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty())
    throw io::InputError(folder.string(), "", "no matrix file (*.json) in the folder");
  return files;
}

std::string command_line(const BenchParetoCommand& command, bool matrices_given,
                         const std::vector<fs::path>& matrices) {
  std::string line = "brb bench pareto";
  if (matrices_given) {
    line += " --matrix";
    for (const fs::path& file : matrices)
      line += " " + file.string();
  }
  line += " --out " + command.output_directory.string();
  if (command.repeats)
    line += " --repeats " + std::to_string(*command.repeats);
  line += " --jobs " + std::to_string(command.jobs);
  if (command.quick)
    line += " --quick";
  if (command.run_committed)
    line += " --run-committed";
  return line;
}

} // namespace

CLI::App* add_bench_pareto_command(CLI::App& bench, BenchParetoCommand& command) {
  auto* pareto = bench.add_subcommand(
      "pareto", "Run time against error: run each matrix's settings (fidelity, core elements, "
                "fibers, mode, step), measure the median wall time and the error against the "
                "finest full setting, and write PARETO.md and pareto.csv with the Pareto fronts.");
  pareto
      ->add_option("--matrix", command.matrices,
                   "Matrix files (README \"brb bench pareto\"); default: bench/pareto/*.json")
      ->type_name("FILE ...");
  pareto
      ->add_option("--out", command.output_directory,
                   "Output directory for PARETO.md and pareto.csv (created if missing; its "
                   "parent must exist); default bench")
      ->type_name("DIR");
  pareto
      ->add_option_function<int>(
          "--repeats",
          [&command](const int& repeats) {
            if (repeats < 1)
              throw CLI::ValidationError("--repeats", "must be a whole number >= 1");
            command.repeats = repeats;
          },
          "Runs per setting (the median time is kept); default: the matrix's")
      ->type_name("N");
  pareto
      ->add_option_function<int>(
          "--jobs",
          [&command](const int& jobs) {
            if (jobs < 1)
              throw CLI::ValidationError("--jobs", "must be a whole number >= 1");
            command.jobs = jobs;
          },
          "Runs at the same time, on threads; default 1 (times of parallel runs share the "
          "cores)")
      ->type_name("N");
  pareto->add_flag("--quick", command.quick,
                   "One run per setting over each matrix's shortened window or protocol "
                   "(\"quick\"): a smoke test, not the study");
  pareto->add_flag("--run-committed", command.run_committed,
                   "Run the settings that name a committed run (\"committed_run\", a brb frame "
                   "summary.json) instead of reading it");
  return pareto;
}

int run_bench_pareto_command(const BenchParetoCommand& command, std::ostream& report,
                             std::ostream& notes) {
  const bool matrices_given = !command.matrices.empty();
  const std::vector<fs::path> files = matrices_given ? command.matrices : default_matrices();
  std::vector<study::ParetoCase> cases;
  for (const fs::path& file : files) {
    study::ParetoCase study_case = study::read_pareto_matrix(file);
    cases.push_back(command.quick ? study_case.quick() : study_case);
  }
  check_output_directory(command.output_directory);

  std::mutex lock;
  study::ParetoRunOptions options;
  options.jobs = command.jobs;
  options.repeats = command.repeats;
  options.run_committed = command.run_committed;
  options.progress = [&](const std::string& line) {
    const std::lock_guard<std::mutex> guard(lock);
    notes << "brb bench pareto: " << line << std::endl;
  };
  const std::vector<study::CaseOutcome> outcomes = study::run_pareto_cases(cases, options);
  int status = kCompleted;
  for (const study::CaseOutcome& outcome : outcomes) {
    const study::ParetoCase& study_case = outcome.study_case;
    const study::SettingOutcome& reference = outcome.settings.at(study_case.reference);
    if (!reference.ran || !reference.stop_reason.empty()) {
      notes << "brb: error: " << study_case.matrix_file.string() << ": the reference setting \""
            << reference.setting.label << "\" "
            << (reference.ran ? "stopped early: " + reference.stop_reason
                              : "failed: " + reference.failure)
            << "; the errors of this case cannot be measured\n";
      status = kReferenceFailed;
    }
  }

  study::ParetoRunDescription description;
  description.command_line = command_line(command, matrices_given, files);
  description.jobs = command.jobs;
  description.repeats = command.repeats;
  description.quick = command.quick;
  fs::create_directory(command.output_directory);
  study::write_pareto_outputs(command.output_directory, outcomes, description);

  for (const study::CaseOutcome& outcome : outcomes) {
    report << "brb bench pareto: " << outcome.study_case.name << " ("
           << study::to_string(outcome.study_case.kind) << "), reference "
           << outcome.settings.at(outcome.study_case.reference).setting.label << "\n";
    for (const study::SettingOutcome& s : outcome.settings) {
      report << "  " << std::left << std::setw(24) << s.setting.label << std::right << std::setw(12)
             << std::setprecision(4) << s.median_time << " s  error " << std::setw(10)
             << std::setprecision(3) << 100.0 * s.errors.primary() << " %"
             << (s.front_primary ? "  front" : "") << "\n";
    }
  }
  report << "  wrote " << (command.output_directory / "PARETO.md").string() << "\n"
         << "        " << (command.output_directory / "pareto.csv").string() << "\n";
  return status;
}

} // namespace brb::cli
