#include "bench_stress_command.hpp"

#include "output_directory.hpp"

#include "brb/io/input_error.hpp"
#include "brb/study/stress_report.hpp"
#include "brb/study/stress_run.hpp"
#include "brb/study/stress_suite.hpp"

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <sstream>

#ifndef BRB_DEFAULT_SHARED_DIR
#error "BRB_DEFAULT_SHARED_DIR (the shared data directory) must be defined by the build"
#endif
#ifndef BRB_DEFAULT_SOURCE_DIR
#error "BRB_DEFAULT_SOURCE_DIR (the source tree, for the default inputs) must be defined"
#endif

namespace brb::cli {

namespace fs = std::filesystem;

namespace {

const fs::path kDefaultBrace =
    fs::path(BRB_DEFAULT_SOURCE_DIR) / "examples/braces/girona_D3_restrained.json";
const fs::path kDefaultFrame = fs::path(BRB_DEFAULT_SOURCE_DIR) / "frames/brbf3/model.json";
const fs::path kDefaultRecord =
    fs::path(BRB_DEFAULT_SHARED_DIR) / "data/ground_motions/Rinaldi228.AT2";

bool selected(const std::string& name, const std::vector<std::string>& only) {
  if (only.empty())
    return true;
  for (const std::string& text : only) {
    if (name.find(text) != std::string::npos)
      return true;
  }
  return false;
}

std::string command_line(const BenchStressCommand& command) {
  std::ostringstream text;
  text << "brb bench stress" << (command.long_suite ? " --long" : "") << " --seed " << command.seed
       << " --jobs " << command.jobs;
  if (!command.only.empty()) {
    text << " --only ";
    for (std::size_t k = 0; k < command.only.size(); ++k)
      text << (k ? "," : "") << command.only[k];
  }
  return text.str();
}

} // namespace

CLI::App* add_bench_stress_command(CLI::App& bench, BenchStressCommand& command) {
  auto* stress = bench.add_subcommand(
      "stress", "The numerical stress suite: random histories up to 20 dy, monotonic "
                "compression to 10 % core strain, step sizes 1/100 to 10 x the default, a "
                "frame at and beyond collapse, near-singular braces. Writes "
                "DIR/stress_report.md and DIR/stress_cases.csv.");
  stress
      ->add_option("--out", command.output_directory,
                   "Output directory (created if missing; its parent must exist); default .")
      ->type_name("DIR");
  stress->add_flag("--long", command.long_suite,
                   "The long suite (more seeds and reversals, 8 core elements, whole record)");
  stress
      ->add_option("--seed", command.seed,
                   "First seed of the random histories (then seed + 1, ...); default 1")
      ->type_name("N");
  stress
      ->add_option("--jobs", command.jobs,
                   "Cases at a time, each on its own thread (default 1); per-step times are "
                   "wall times, so they grow when the threads share cores")
      ->type_name("N")
      ->check(CLI::Range(1, 256));
  command.brace = kDefaultBrace;
  stress->add_option("--brace", command.brace, "Brace file with a steel-tube casing")
      ->type_name("FILE")
      ->default_str(kDefaultBrace.string());
  command.frame = kDefaultFrame;
  stress->add_option("--frame", command.frame, "Frame model file with brb elements")
      ->type_name("FILE")
      ->default_str(kDefaultFrame.string());
  command.record = kDefaultRecord;
  stress->add_option("--record", command.record, "Ground motion (PEER .AT2) of the frame cases")
      ->type_name("FILE")
      ->default_str(kDefaultRecord.string());
  // Hidden: a subset of the cases (the CLI test).
  stress->add_option("--only", command.only, "Cases whose name contains one of these texts")
      ->delimiter(',')
      ->group("");
  stress->footer("Exit status: 0 every case met the acceptance (no NaN, completed or a stated "
                 "failure reason, energy-balance error < 1 % of the input work), 1 a case did "
                 "not (the report says which), 2 invalid input or usage (nothing is run).");
  return stress;
}

int run_bench_stress_command(const BenchStressCommand& command, std::ostream& out) {
  const auto started = std::chrono::steady_clock::now();
  // Every input is read and checked before the first case runs.
  check_output_directory(command.output_directory);
  const study::StressSuiteInputs inputs{command.brace, command.frame, command.record};
  std::vector<study::StressCase> cases;
  for (study::StressCase& stress_case :
       study::make_stress_suite(inputs, {command.long_suite, command.seed})) {
    if (selected(stress_case.name, command.only))
      cases.push_back(std::move(stress_case));
  }
  if (cases.empty())
    throw io::InputError("command line", "--only", "no stress case has a name containing it");

  out << "brb bench stress: " << cases.size() << " cases ("
      << (command.long_suite ? "long" : "short") << " suite, seed " << command.seed << ", "
      << command.jobs << " jobs)\n";
  std::size_t done = 0;
  const std::vector<study::StressResult> results =
      study::run_stress_cases(cases, command.jobs, [&](const study::StressResult& result) {
        ++done;
        out << "  [" << done << "/" << cases.size() << "] " << result.name << ": " << result.outcome
            << "; energy error " << std::setprecision(3) << result.energy_error << ", NaN "
            << result.nan_count << ", " << result.fallbacks.total() << " fallbacks, " << std::fixed
            << std::setprecision(2) << result.wall_time << " s" << std::defaultfloat
            << (result.acceptable() ? "" : "  FAILS: " + result.acceptance_failure()) << "\n"
            << std::flush;
      });

  study::StressReportContext context;
  context.command = command_line(command);
  context.long_suite = command.long_suite;
  context.seed = command.seed;
  context.jobs = command.jobs;
  context.inputs = inputs;
  context.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  fs::create_directories(command.output_directory);
  study::write_stress_report(command.output_directory, cases, results, context);

  const study::StressSummary summary = study::summarise(results);
  out << "  completion " << summary.completed << " of " << summary.cases << ", NaN "
      << summary.nan_count << ", max energy error " << std::setprecision(3)
      << summary.max_energy_error << " (" << summary.max_energy_error_case << "), fallbacks "
      << summary.fallbacks.total() << "\n"
      << "  "
      << (summary.unacceptable == 0
              ? "every case meets the acceptance"
              : std::to_string(summary.unacceptable) + " cases break the acceptance")
      << "\n  wrote " << (command.output_directory / "stress_report.md").string() << "\n        "
      << (command.output_directory / "stress_cases.csv").string() << "\n";
  return summary.unacceptable == 0 ? 0 : 1;
}

} // namespace brb::cli
