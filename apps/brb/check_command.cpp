#include "check_command.hpp"

#include "output_directory.hpp"

#include "brb/design/check.hpp"
#include "brb/design/check_input.hpp"
#include "brb/design/check_report.hpp"
#include "brb/io/atomic_file.hpp"
#include "brb/io/csv.hpp"
#include "brb/io/cyclic_output.hpp"

#include <iomanip>
#include <sstream>
#include <string>

namespace brb::cli {
namespace {

using io::significant;

namespace fs = std::filesystem;

constexpr int kCompleted = 0;
constexpr int kStoppedEarly = 1;

constexpr const char* kHysteresisFile = "hysteresis.csv";
constexpr const char* kCheckJsonFile = "check.json";
constexpr const char* kCheckMarkdownFile = "check.md";

} // namespace

CLI::App* add_check_command(CLI::App& app, CheckCommand& command) {
  auto* check = app.add_subcommand(
      "check", "AISC 341 check of a brace: virtual qualification test (K3.4c sequence at full "
               "fidelity), acceptance criteria, adjusted strengths, drift capacity.");
  check
      ->add_option("check", command.check,
                   "Check file, JSON (comments allowed); schema in the "
                   "README, \"brb check\"")
      ->type_name("CHECK.json")
      ->required();
  check
      ->add_option("--out", command.output_directory,
                   "Output directory (created if missing; its parent must exist): check.json, "
                   "check.md, hysteresis.csv")
      ->type_name("DIR")
      ->required();
  check->footer("Outputs (README, \"brb check\"): check.json (values, criteria, verdict),\n"
                "check.md (tables), hysteresis.csv (the qualification test, as brb cyclic).\n"
                "Units: N, mm, MPa. Exit status: 0 the check ran (PASS or FAIL is in the\n"
                "outputs), 1 the run failed, 2 invalid input or usage (nothing written).");
  return check;
}

int run_check_command(const CheckCommand& command, std::ostream& report, std::ostream& notes) {
  // Every input is read and checked before anything is written.
  const design::CheckSpec check = design::read_check(command.check);
  check_output_directory(command.output_directory);

  const design::CheckResult result = design::run_check(check);
  for (const std::string& warning : result.warnings)
    notes << "brb: warning: " << check.brace_source << ": " << warning << "\n";

  fs::create_directory(command.output_directory);
  const fs::path hysteresis = command.output_directory / kHysteresisFile;
  const fs::path json = command.output_directory / kCheckJsonFile;
  const fs::path markdown = command.output_directory / kCheckMarkdownFile;
  io::write_file_atomically(hysteresis, io::hysteresis_table(result.qualification.test).text());
  io::write_file_atomically(json, design::check_json(check, result).dump(2) + "\n");
  io::write_file_atomically(markdown, design::check_markdown(check, result));

  const design::QualificationResult& q = result.qualification;
  report << "brb check: " << check.name << " (" << command.check.string() << "), AISC "
         << design::to_string(check.edition.edition) << "\n"
         << "  brace " << check.brace_source
         << ": Delta_by = " << significant(result.yield_deformation, 6)
         << " mm, Pysc = " << significant(result.forces.tested, 6) << " N\n"
         << "  Delta_bm = " << significant(result.demand.design_deformation, 6) << " mm ("
         << significant(result.demand.design_deformation / result.yield_deformation, 4)
         << " Delta_by) from a story drift of " << significant(result.demand.used_story_drift, 6)
         << " mm\n"
         << "  " << q.cycles.size() << " cycles (" << q.extra_cycles
         << " at 1.5 Delta_bm), cumulative inelastic deformation "
         << significant(q.test.indicators.cumulative_inelastic_deformation, 5) << " Delta_by\n"
         << "  beta = " << significant(q.beta, 4) << ", omega = " << significant(q.omega, 4)
         << "\n";
  for (const design::Criterion& criterion : q.criteria) {
    report << "  " << (criterion.passed ? "pass " : "FAIL ") << criterion.id << ": "
           << criterion.description << ": " << significant(criterion.value, 5) << " "
           << criterion.comparison << " " << significant(criterion.limit, 5) << "\n";
  }
  if (result.drift_capacity) {
    const design::DriftCapacity& capacity = *result.drift_capacity;
    report << "  drift capacity: "
           << (capacity.drift_ratio ? significant(*capacity.drift_ratio, 4) : std::string("none"))
           << (capacity.upper_passed ? " (or more)" : "") << " (bracket "
           << significant(capacity.bracket, 3) << ", " << capacity.trials.size() << " runs)\n";
  }
  report << "  verdict: " << design::verdict(result) << "\n"
         << "  wrote " << json.string() << "\n"
         << "        " << markdown.string() << "\n"
         << "        " << hysteresis.string() << "\n";
  if (!q.test.completed) {
    notes << "brb: error: " << command.check.string()
          << ": the qualification test stopped early: " << q.test.stop_reason << "\n";
    return kStoppedEarly;
  }
  return kCompleted;
}

} // namespace brb::cli
