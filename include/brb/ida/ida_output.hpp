// The results of an IDA, written atomically into the output directory (README, "brb ida"):
//   ida_points.csv        one row per run (record, IM, scale, demands, collapse kind, time)
//   ida_curves.csv        each record's curve: runs below its lowest collapse, then the flatline
//   ida_fractiles.csv     16/50/84 % fractiles of IM given the peak story drift
//   collapse_fragility.csv the fitted lognormal fragility and the empirical collapse fraction
//   summary.json          settings, T1, per-record capacities, fragility, CMR, counts
// Every number is a function of the points alone (run times aside), so a resumed IDA writes
// the same files as an uninterrupted one.
#pragma once

#include "brb/ida/ida_point.hpp"
#include "brb/ida/ida_study.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <vector>

namespace brb::ida {

struct IdaRunDescription {
  std::string model_file;
  std::string suite_file;
  int jobs = 1;
  std::string parallelism = "threads"; ///< "threads" or "mpi"
  double wall_time = 0.0;              ///< s, this session
  std::size_t runs_this_session = 0;
};

/// The drift levels of the fractile table: 40 levels from limit/40 to the drift limit.
std::vector<double> fractile_drift_levels(double drift_limit);

/// Writes the files; returns the content of summary.json.
nlohmann::json write_ida_outputs(const std::filesystem::path& directory, const IdaStudy& study,
                                 const std::vector<IdaPoint>& points,
                                 const IdaRunDescription& description);

} // namespace brb::ida
