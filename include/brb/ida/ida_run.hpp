// Running an IDA on the threads of one machine: records go to a pool of `jobs` threads (a
// record's trace is sequential: each run decides the next), every finished run is appended
// to the journal, and the points come back sorted by record and intensity, identical for
// any number of threads.
#pragma once

#include "brb/ida/ida_study.hpp"
#include "brb/ida/journal.hpp"

#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <ostream>
#include <vector>

namespace brb::ida {

/// The progress line: runs done (and how many came from the journal), collapses, an
/// estimate of the runs left (each unfinished record may use its whole budget) and of the
/// time left (at the rate of this session's runs). Thread-safe.
class IdaProgress {
public:
  IdaProgress(std::ostream* out, std::size_t records, int max_runs);
  /// Counts the runs a resumed study takes from its journal (grouped by record).
  void journal_points(const std::vector<std::map<double, IdaPoint>>& known);
  void run_finished(const IdaPoint& point);
  void record_finished(std::size_t runs);
  std::size_t runs_done() const { return done_; }

private:
  void print();
  std::ostream* out_;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::size_t records_left_;
  int max_runs_;
  std::size_t done_ = 0, from_journal_ = 0, collapses_ = 0, runs_of_finished_records_ = 0;
  std::size_t runs_of_open_records_ = 0;
};

/// Journal entries grouped by record (index) and intensity. Throws std::invalid_argument
/// for a malformed entry or a record index outside the suite.
std::vector<std::map<double, IdaPoint>> points_by_record(const std::vector<nlohmann::json>& entries,
                                                         std::size_t records);

/// Every point of every record, sorted by (record, intensity).
std::vector<IdaPoint> sorted_points(std::vector<IdaPoint> points);

/// Runs the traces of all records on `jobs` threads (>= 1), taking the runs the journal
/// already holds from `known` and appending new ones to `journal`. The first exception of a
/// worker stops the others and is rethrown.
std::vector<IdaPoint> run_ida_threads(const IdaStudy& study, Journal& journal,
                                      const std::vector<std::map<double, IdaPoint>>& known,
                                      int jobs, IdaProgress& progress);

} // namespace brb::ida
