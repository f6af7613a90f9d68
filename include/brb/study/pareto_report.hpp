// The outputs of `brb bench pareto`: bench/PARETO.md (generated tables per case, the Pareto
// fronts marked, the cheapest setting within the acceptance bound, the `auto` check) and
// pareto.csv (one row per case and setting), both written atomically (io::AtomicFile).
#pragma once

#include "brb/study/pareto_runner.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brb::study {

/// The acceptance bound of issue 9: a setting within 2 % of the finest `full` setting's
/// energy (components) or peak drift (frames).
inline constexpr double kAcceptanceError = 0.02;

/// The cheapest setting (smallest median time) whose primary error is at most `bound`.
std::optional<std::size_t> cheapest_within(const CaseOutcome& outcome, double bound);

/// How the study was run, for the page's header.
struct ParetoRunDescription {
  std::string command_line;
  int jobs = 1;
  std::optional<int> repeats;
  bool quick = false;
};

/// pareto.csv: a header line and one row per case and setting (columns in the README).
std::string pareto_csv(const std::vector<CaseOutcome>& outcomes);

/// PARETO.md.
std::string pareto_markdown(const std::vector<CaseOutcome>& outcomes,
                            const ParetoRunDescription& description);

/// Writes `directory`/PARETO.md and `directory`/pareto.csv (the directory must exist).
void write_pareto_outputs(const std::filesystem::path& directory,
                          const std::vector<CaseOutcome>& outcomes,
                          const ParetoRunDescription& description);

} // namespace brb::study
