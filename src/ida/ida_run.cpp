#include "brb/ida/ida_run.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace brb::ida {
namespace {

std::string duration_text(double seconds) {
  std::ostringstream text;
  const auto whole = static_cast<long>(std::lround(seconds));
  if (whole >= 3600)
    text << whole / 3600 << "h" << std::setw(2) << std::setfill('0') << (whole % 3600) / 60 << "m";
  else if (whole >= 60)
    text << whole / 60 << "m" << std::setw(2) << std::setfill('0') << whole % 60 << "s";
  else
    text << whole << "s";
  return text.str();
}

} // namespace

IdaProgress::IdaProgress(std::ostream* out, std::size_t records, int max_runs)
    : out_(out), records_left_(records), max_runs_(max_runs) {}

void IdaProgress::journal_points(const std::vector<std::map<double, IdaPoint>>& known) {
  const std::lock_guard lock(mutex_);
  for (const auto& record_points : known) {
    for (const auto& [intensity, point] : record_points) {
      ++done_;
      ++from_journal_;
      ++runs_of_open_records_;
      collapses_ += point.collapsed() ? 1 : 0;
    }
  }
}

void IdaProgress::run_finished(const IdaPoint& point) {
  const std::lock_guard lock(mutex_);
  ++done_;
  ++runs_of_open_records_;
  collapses_ += point.collapsed() ? 1 : 0;
  print();
}

void IdaProgress::record_finished(std::size_t runs) {
  const std::lock_guard lock(mutex_);
  records_left_ -= records_left_ > 0 ? 1 : 0;
  runs_of_finished_records_ += runs;
  runs_of_open_records_ -= std::min(runs, runs_of_open_records_);
}

void IdaProgress::print() {
  if (out_ == nullptr)
    return;
  const std::size_t budget = records_left_ * static_cast<std::size_t>(max_runs_);
  const std::size_t left = budget > runs_of_open_records_ ? budget - runs_of_open_records_ : 0;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const std::size_t this_session = done_ - from_journal_;
  *out_ << "ida: " << done_ << " runs done";
  if (from_journal_ > 0)
    *out_ << " (" << from_journal_ << " from the journal)";
  *out_ << ", " << collapses_ << " collapses, at most " << left << " to go, "
        << duration_text(elapsed) << " elapsed";
  if (this_session > 0)
    *out_ << ", at most "
          << duration_text(elapsed / static_cast<double>(this_session) * static_cast<double>(left))
          << " left";
  *out_ << std::endl;
}

std::vector<std::map<double, IdaPoint>> points_by_record(const std::vector<nlohmann::json>& entries,
                                                         std::size_t records) {
  std::vector<std::map<double, IdaPoint>> known(records);
  for (const nlohmann::json& entry : entries) {
    IdaPoint point = point_from_json(entry);
    if (point.record < 0 || static_cast<std::size_t>(point.record) >= records)
      throw std::invalid_argument("journal entry for record " + std::to_string(point.record) +
                                  ", which is not in the suite");
    known[static_cast<std::size_t>(point.record)].emplace(point.intensity, std::move(point));
  }
  return known;
}

std::vector<IdaPoint> sorted_points(std::vector<IdaPoint> points) {
  std::sort(points.begin(), points.end(), [](const IdaPoint& a, const IdaPoint& b) {
    return a.record != b.record ? a.record < b.record : a.intensity < b.intensity;
  });
  return points;
}

std::vector<IdaPoint> run_ida_threads(const IdaStudy& study, Journal& journal,
                                      const std::vector<std::map<double, IdaPoint>>& known,
                                      int jobs, IdaProgress& progress) {
  if (jobs < 1)
    throw std::invalid_argument("the number of jobs must be >= 1");
  const std::size_t records = study.record_count();
  progress.journal_points(known);
  std::vector<std::vector<IdaPoint>> traced(records);
  std::atomic<std::size_t> next_record{0};
  std::atomic<bool> stop{false};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    try {
      for (std::size_t record = next_record++; record < records && !stop; record = next_record++) {
        traced[record] = study.trace(record, known.at(record), [&](const IdaPoint& point) {
          if (stop)
            throw std::runtime_error("stopped"); // another worker failed
          journal.append(to_json(point));
          progress.run_finished(point);
        });
        progress.record_finished(traced[record].size());
      }
    } catch (...) {
      const std::lock_guard lock(failure_mutex);
      if (!failure && !stop)
        failure = std::current_exception();
      stop = true;
    }
  };
  const auto threads = static_cast<std::size_t>(
      std::min<long>(jobs, static_cast<long>(std::max<std::size_t>(records, 1))));
  {
    std::vector<std::jthread> pool;
    for (std::size_t t = 1; t < threads; ++t)
      pool.emplace_back(work);
    work();
  }
  if (failure)
    std::rethrow_exception(failure);
  std::vector<IdaPoint> points;
  for (auto& record_points : traced)
    points.insert(points.end(), record_points.begin(), record_points.end());
  return sorted_points(std::move(points));
}

} // namespace brb::ida
