// The two result files of a virtual cyclic test (README "brb cyclic"): hysteresis.csv and
// summary.json. `brb cyclic` and `brb validate` write the same files from these builders, so
// their columns and keys are documented (and can change) in one place.
#pragma once

#include "brb/analysis/cyclic_test.hpp"
#include "brb/io/csv.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace brb::io {

/// Analysis steps that converged (the initial, unloaded state is not a step).
int converged_steps(const analysis::CyclicTestResult& result);

/// hysteresis.csv: step,cycle,deformation,force,max_lateral_displacement,substeps, one row
/// per converged step (step 0: the unloaded initial state).
NumericTable hysteresis_table(const analysis::CyclicTestResult& result);

/// summary.json: the brace's name, dy (mm) and Py (N), peak forces, energy per cycle,
/// completion, solver statistics, energy balance and the brace indicators (README keys).
nlohmann::ordered_json cyclic_summary_json(const std::string& brace_name, double yield_deformation,
                                           double yield_force,
                                           const analysis::CyclicTestResult& result);

} // namespace brb::io
