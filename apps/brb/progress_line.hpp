// Progress lines of long cyclic analyses: `brb cyclic --progress` and `brb validate --progress`
// (the lab records take minutes to hours, and their reports come only at the end).
#pragma once

#include "brb/analysis/cyclic_test.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstddef>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>

namespace brb::cli {

/// An analysis::StepObserver that prints "<label>step k of N (p %), deformation d mm, force
/// f N, s <counted>, t s" (the steps' `substeps` summed so far, wall time since it was made)
/// at most every `interval` seconds of wall time (0: after every step) and after the last
/// step. `counted` names what `substeps` counts ("explicit steps" for brb solid's records).
/// `lock`, when given, guards `out` for runs that share it on several threads.
class ProgressLine {
public:
  ProgressLine(std::ostream& out, std::string label, std::size_t steps, double interval,
               std::mutex* lock = nullptr, std::string counted = "substeps");

  void operator()(const analysis::CyclicStep& step);

private:
  std::ostream* out_;
  std::string label_;
  std::string counted_;
  std::size_t steps_;
  double interval_;
  std::mutex* lock_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_;
  long long substeps_ = 0;
};

/// Registers `--progress SECONDS` (a number >= 0, stored into `interval`) on `command`.
void add_progress_option(CLI::App& command, std::optional<double>& interval,
                         const std::string& description);

} // namespace brb::cli
