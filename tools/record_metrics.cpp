// brb_record_metrics: the issue-4 record metrics of a `brb cyclic` run driven by a protocol
// that `brb calibrate --protocol-out` extracted from a laboratory record. A measuring tool
// until `brb validate` computes the metric kinds record_nrms, record_cycle_energy and
// record_beta itself with the same library functions (validation/record_comparison.hpp).
//
//   brb_record_metrics RUN_DIR PROTOCOL.csv RECORD.json [--shared DIR] [--energy-floor F]
//
// RUN_DIR holds hysteresis.csv and summary.json of the run; model step k is protocol point
// k (the protocol's steps are under the cyclic command's dy / 10, so it adds no point).
// PROTOCOL.csv has the columns deformation and record_row (-1: not a record point).
// RECORD.json is a metrics.json (its "reference") or a bare reference object. Prints one JSON
// object on stdout. Exit status 2 on an input error.
#include "brb/io/csv.hpp"
#include "brb/io/force_record.hpp"
#include "brb/io/input_error.hpp"
#include "brb/io/json_input.hpp"
#include "brb/validation/record_comparison.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

int run(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: brb_record_metrics RUN_DIR PROTOCOL.csv RECORD.json [--shared DIR] "
                 "[--energy-floor F] [--threshold-dy T]\n";
    return 2;
  }
  const fs::path run_directory = argv[1];
  const fs::path protocol_file = argv[2];
  const fs::path record_json = argv[3];
  std::optional<fs::path> shared;
  double energy_floor = 0.05;
  double threshold_dy = 0.1;
  for (int i = 4; i + 1 < argc; i += 2) {
    const std::string option = argv[i];
    if (option == "--shared")
      shared = argv[i + 1];
    else if (option == "--energy-floor")
      energy_floor = std::stod(argv[i + 1]);
    else if (option == "--threshold-dy")
      threshold_dy = std::stod(argv[i + 1]);
  }

  const nlohmann::json summary = brb::io::read_json_file(run_directory / "summary.json");
  const double dy = summary.at("yield_deformation").get<double>();
  const auto steps = brb::io::read_numeric_column(run_directory / "hysteresis.csv", "step");
  const auto forces = brb::io::read_numeric_column(run_directory / "hysteresis.csv", "force");
  const auto rows = brb::io::read_numeric_column(protocol_file, "record_row");
  const auto points = brb::io::read_numeric_column(protocol_file, "deformation");

  const nlohmann::json document = brb::io::read_json_file(record_json);
  const brb::io::JsonValue root(document, record_json.string());
  const fs::path base =
      record_json.parent_path().empty() ? fs::path(".") : record_json.parent_path();
  const fs::path shared_directory =
      shared ? *shared : brb::io::find_shared_directory(base).value_or(fs::path("shared"));
  const brb::io::ForceRecordReference reference = brb::io::read_force_record_reference(
      document.contains("reference") ? *root.find("reference") : root, base, shared_directory);
  const brb::io::ForceRecord record = brb::io::read_force_record(reference.file, reference.format);

  // Model step k = protocol point k; compare where the point is a record row.
  const std::vector<double> record_force =
      brb::io::record_force_at_rows(record, rows, protocol_file, "record_row");
  std::vector<double> deformation, test_force, model_force;
  std::size_t model_steps = 0;
  for (std::size_t i = 0; i < steps.values.size(); ++i) {
    const auto k = static_cast<std::size_t>(steps.values[i]);
    model_steps = std::max(model_steps, k);
    if (k >= record_force.size() || std::isnan(record_force[k]))
      continue;
    deformation.push_back(points.values[k]);
    test_force.push_back(record_force[k]);
    model_force.push_back(forces.values[i]);
  }
  // beta on the cycles whose test peaks reach the yield force, as brb validate compares
  const double yield_force = summary.at("yield_force").get<double>();
  const brb::validation::RecordComparison comparison = brb::validation::compare_with_record(
      deformation, test_force, model_force, {threshold_dy * dy, energy_floor, yield_force});

  nlohmann::ordered_json out;
  out["run"] = run_directory.string();
  out["completed"] = summary.at("completed");
  out["model_steps"] = model_steps;
  out["protocol_points"] = rows.values.size() - 1;
  out["compared_points"] = deformation.size();
  out["normalised_rms_error"] = comparison.normalised_rms_error;
  out["cycles"] = comparison.cycles.size();
  out["scored_cycles"] = comparison.scored_cycles;
  out["max_cycle_energy_error"] = comparison.max_cycle_energy_error;
  out["max_beta_difference"] = comparison.max_beta_difference;
  out["beta_cycles"] = comparison.beta_cycles;
  // AISC 341 F4.2a from the scored cycles: beta = Pmax / Tmax and Tmax (omega = Tmax / Pysc),
  // the largest over the cycles, for the test and for the model at the same points.
  nlohmann::ordered_json per_cycle = nlohmann::ordered_json::array();
  for (const auto& cycle : comparison.cycles) {
    if (!cycle.scored)
      continue;
    per_cycle.push_back({{"amplitude_mm", std::max(std::abs(deformation[cycle.span.first]),
                                                   std::abs(deformation[cycle.span.last]))},
                         {"test_energy", cycle.test_energy},
                         {"model_energy", cycle.model_energy},
                         {"test_beta", cycle.test_beta},
                         {"model_beta", cycle.model_beta},
                         {"test_tmax", cycle.test_peaks.tension},
                         {"model_tmax", cycle.model_peaks.tension}});
  }
  out["largest_test_beta"] = comparison.largest_test_beta;
  out["largest_model_beta"] = comparison.largest_model_beta;
  out["largest_test_tmax"] = comparison.largest_test_tension;
  out["largest_model_tmax"] = comparison.largest_model_tension;
  out["scored"] = per_cycle;
  std::cout << out.dump(1) << "\n";
  return 0;
}

} // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const brb::io::InputError& error) {
    std::cerr << "brb_record_metrics: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "brb_record_metrics: error: " << error.what() << "\n";
    return 1;
  }
}
