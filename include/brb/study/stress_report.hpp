// The stress suite's report files (`brb bench stress`): DIR/stress_report.md, a generated
// Markdown report (the totals, then a table per case group), and DIR/stress_cases.csv, one
// row per case. Both written atomically (io::AtomicFile).
#pragma once

#include "brb/study/stress_case.hpp"
#include "brb/study/stress_result.hpp"
#include "brb/study/stress_suite.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace brb::study {

/// What the report says about how it was made (command line, seed, jobs, inputs).
struct StressReportContext {
  std::string command;
  bool long_suite = false;
  std::uint64_t seed = 1;
  int jobs = 1;
  StressSuiteInputs inputs;
  double wall_time = 0.0; ///< s, the whole suite
};

/// The CSV columns: name,group,completed,collapsed,nan_count,energy_error,input_work,
/// steps,planned_steps,fallbacks_substeps,fallbacks_far_branch_cuts,fallbacks_pseudo_transient,
/// fallbacks_unstable_accepted,fallbacks_energy_cuts,fallbacks_modified_newton,
/// fallbacks_broyden,step_time_median,step_time_p90,step_time_max,failed_step_time,wall_time,
/// acceptable,
/// outcome (times in s; outcome quoted).
std::string stress_cases_csv(const std::vector<StressCase>& cases,
                             const std::vector<StressResult>& results);
std::string stress_report_markdown(const std::vector<StressCase>& cases,
                                   const std::vector<StressResult>& results,
                                   const StressReportContext& context);
/// Writes both files into `directory` (which must exist), the CSV first.
void write_stress_report(const std::filesystem::path& directory,
                         const std::vector<StressCase>& cases,
                         const std::vector<StressResult>& results,
                         const StressReportContext& context);

} // namespace brb::study
