// A brace driven from 0 to one target deformation in equal steps, as one cycle: the
// monotonic runs of the slow tests (casing crack-through, casing splitting).
#pragma once

#include "brb/analysis/cyclic_test.hpp"
#include "brb/model/brace_model.hpp"

#include <vector>

namespace brb::test {

/// Runs `brace` from 0 to `target` (mm) in `steps` equal steps, one cycle of amplitude
/// |target|.
inline analysis::CyclicTestResult run_monotonic(model::BraceModel& brace, double target,
                                                int steps) {
  std::vector<double> deformation;
  for (int k = 0; k <= steps; ++k)
    deformation.push_back(target * k / steps);
  const std::vector<int> cycle(deformation.size(), 1);
  const std::vector<double> amplitude{-target};
  return analysis::run_cyclic_test(brace, deformation, cycle, amplitude);
}

} // namespace brb::test
