// Running one stress case (issue 9) and checking everything it produced: every output number
// and the final energies are scanned for NaN and infinity, the energy balance is closed, the
// solver's fallbacks are counted and each step is timed (steady clock, wall time).
#pragma once

#include "brb/study/stress_case.hpp"
#include "brb/study/stress_result.hpp"

#include <functional>
#include <vector>

namespace brb::study {

/// Runs the case. Never throws for a failed analysis: an exception while building or running
/// the case becomes a failure reason ("exception: ..."), so every case reports.
StressResult run_stress_case(const StressCase& stress_case);

/// Runs `cases` on `jobs` threads (>= 1; cases are independent), results in the order of
/// `cases` whatever the thread count. `finished` (optional) is called after each case,
/// from the thread that ran it, one call at a time.
std::vector<StressResult>
run_stress_cases(const std::vector<StressCase>& cases, int jobs,
                 const std::function<void(const StressResult&)>& finished = {});

} // namespace brb::study
