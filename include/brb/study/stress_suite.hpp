// The stress suite of issue 9: the short version (ctest -L stress: every group, `truss` and
// `full` braces with 4 core elements, short histories, a few seconds of record) and the
// long one (`brb bench stress --long`: more seeds, longer histories, 8 core elements, the
// whole record). Both are lists of StressCase made by stress_generators.hpp from three
// inputs: a brace with a steel-tube casing (the reference brace, Girona D3 restrained), a
// frame with BRBs (brbf3) and a ground-motion record.
#pragma once

#include "brb/study/stress_case.hpp"
#include "brb/study/stress_result.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace brb::study {

struct StressSuiteInputs {
  std::filesystem::path brace;  ///< brace file with a steel-tube casing
  std::filesystem::path frame;  ///< frame model file with `brb` elements
  std::filesystem::path record; ///< PEER .AT2 record (units from its header)
};

struct StressSuiteSettings {
  bool long_suite = false;
  std::uint64_t seed = 1; ///< first seed of the random histories (seed, seed + 1, ...)
};

/// The record scales of the frame group, as multiples of the record: chosen on brbf3 under
/// Rinaldi228 (truss braces), which first exceeds 10 % drift between 1 and 2 x the record
/// (measured: peak drift 5.1 % at 1 x, collapse at 2 x; README "Numerical stress tests").
/// The suite runs below, at and beyond it with the model's drift limit (the run stops at
/// the collapse), and the scales of beyond_collapse_scales() with the limit raised to
/// kBeyondCollapseDriftLimit, so that the solver is driven on into the collapse.
std::vector<double> frame_collapse_scales(bool long_suite);
std::vector<double> beyond_collapse_scales(bool long_suite);
inline constexpr double kBeyondCollapseDriftLimit = 0.5;

/// The cases, in group order (all_stress_groups()). Reads the three inputs (io::InputError
/// naming the file and field when one is missing or invalid); throws std::invalid_argument
/// when the brace has no steel-tube casing.
std::vector<StressCase> make_stress_suite(const StressSuiteInputs& inputs,
                                          const StressSuiteSettings& settings);

/// The suite's totals: the numbers the issue asks the report to give.
struct StressSummary {
  int cases = 0;
  int completed = 0;
  int collapsed = 0;          ///< frames that reached the drift limit (completed runs)
  int failed_with_reason = 0; ///< not completed, reason stated
  int nan_count = 0;          ///< over all cases
  double max_energy_error = 0.0;
  std::string max_energy_error_case;
  FallbackCounts fallbacks; ///< summed over the cases
  int steps = 0;
  TimeDistribution step_times; ///< over every step of every case
  int unacceptable = 0;        ///< cases that break the acceptance
  double completion_rate() const { return cases > 0 ? double(completed) / cases : 0.0; }
};
StressSummary summarise(const std::vector<StressResult>& results);

} // namespace brb::study
