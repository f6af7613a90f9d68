// The result files of a virtual cyclic test (README "brb cyclic"): hysteresis.csv,
// summary.json and, when asked, element_history.csv and shape.csv. `brb cyclic` and `brb validate`
// write the same files from these builders, so their columns and keys are documented (and can
// change) in one place.
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

/// element_history.csv: the element outputs after every step (result.history, recorded when
/// run_cyclic_test was asked to): step, core strain, dissipated energy, the running maxima of
/// the brace indicators and its flags as 0/1 (README keys).
NumericTable element_history_table(const analysis::CyclicTestResult& result);

/// shape.csv: the brace's deformed shape after the asked steps (result.shapes, recorded with
/// `--shape-steps`): step, node, position, lateral_y, lateral_z, station, casing_lateral_y,
/// casing_lateral_z, bearing_force_y, bearing_force_z, mortar_damage (README "brb cyclic").
NumericTable brace_shape_table(const analysis::CyclicTestResult& result);

} // namespace brb::io
