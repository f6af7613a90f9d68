// Cross-specimen contrasts (validation/contrasts.json): qualitative statements that compare a
// metric of one specimen with a metric of another, e.g. "G1's compression/tension asymmetry
// is larger than G3's" (BRB_SOURCE_FACTS section 8). Checked at every refinement both
// specimens ran at.
#pragma once

#include "brb/validation/specimen.hpp"
#include "brb/validation/specimen_run.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace brb::validation {

/// `left.metric` of `left.specimen` stands in `relation` (">" or "<") to `right.metric` of
/// `right.specimen`.
struct ContrastSpec {
  struct Operand {
    std::string specimen;
    std::string metric;
  };
  std::string name;
  std::string statement; ///< the claim in words
  std::string source;
  Operand left;
  std::string relation; ///< ">" or "<"
  Operand right;
};

/// The name of the contrasts file in the validation folder (optional).
inline constexpr const char* contrasts_file_name = "contrasts.json";

/// Reads a contrasts file; every operand must name a specimen of `specimens` and a metric of
/// it that is not a flag. Throws io::InputError naming the file and JSON path.
std::vector<ContrastSpec> read_contrasts(const std::filesystem::path& file,
                                         const std::vector<Specimen>& specimens);

/// The results of the runs of one specimen.
struct SpecimenOutcome {
  Specimen specimen;
  double yield_deformation = 0.0;
  double yield_force = 0.0;
  std::vector<RunOutcome> runs;
};

struct ContrastResult {
  ContrastSpec contrast;
  std::optional<int> refinement; ///< empty when the two specimens share no run
  std::optional<double> left;
  std::optional<double> right;
  CheckStatus status = CheckStatus::reported; ///< reported: not run (not counted)
  std::string note;
};

/// Each contrast at every refinement both specimens ran at; a contrast whose specimens did
/// not both run (e.g. --only) gives one `reported` result saying so; one whose metric has no
/// value fails.
std::vector<ContrastResult> evaluate_contrasts(const std::vector<ContrastSpec>& contrasts,
                                               const std::vector<SpecimenOutcome>& outcomes);

} // namespace brb::validation
