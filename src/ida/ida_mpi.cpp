#include "brb/ida/ida_mpi.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>

#ifdef BRB_WITH_MPI
#include <mpi.h>
#endif

namespace brb::ida::mpi {

bool available() {
#ifdef BRB_WITH_MPI
  return true;
#else
  return false;
#endif
}

bool launched_with_several_ranks() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* value = std::getenv(variable))
      return std::atoi(value) > 1;
  }
  return false;
}

#ifndef BRB_WITH_MPI

Session::Session() {
  throw std::runtime_error("this brb was built without MPI: configure with -DBRB_WITH_MPI=ON");
}
Session::~Session() = default;
bool Session::broadcast_go(bool go) const {
  return go;
}
std::vector<IdaPoint> run_master(const Session&, const IdaStudy&, Journal&,
                                 const std::vector<std::map<double, IdaPoint>>&, IdaProgress&) {
  throw std::runtime_error("this brb was built without MPI");
}
void run_worker(const Session&, const IdaStudy&) {
  throw std::runtime_error("this brb was built without MPI");
}

#else

namespace {

// Message tags of the master/worker protocol.
enum Tag : int {
  kReady = 1, ///< worker -> master: give me a record (empty)
  kTask = 2,  ///< master -> worker: the record index and its journal points (JSON text)
  kStop = 3,  ///< master -> worker: no more work (empty)
  kPoint = 4, ///< worker -> master: a finished run (JSON text)
  kDone = 5,  ///< worker -> master: the trace of its record is complete (JSON: intensities)
  kError = 6, ///< worker -> master: an error other than a failed analysis (text)
};

void send_text(const std::string& text, int destination, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, destination, tag, MPI_COMM_WORLD);
}

/// Receives the message `status` announced (MPI_Probe) as text.
std::string receive_text(const MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::string text(static_cast<std::size_t>(count), '\0');
  MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return text;
}

} // namespace

Session::Session() {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

Session::~Session() {
  MPI_Finalize();
}

bool Session::broadcast_go(bool go) const {
  int flag = go ? 1 : 0;
  MPI_Bcast(&flag, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return flag != 0;
}

std::vector<IdaPoint> run_master(const Session& session, const IdaStudy& study, Journal& journal,
                                 const std::vector<std::map<double, IdaPoint>>& known,
                                 IdaProgress& progress) {
  progress.journal_points(known);
  std::vector<std::map<double, IdaPoint>> record_points = known;
  std::vector<IdaPoint> points;
  std::size_t next_record = 0;
  int working = session.size() - 1;
  std::string failure;
  while (working > 0) {
    MPI_Status status;
    MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    const std::string text = receive_text(status);
    const int worker = status.MPI_SOURCE;
    switch (status.MPI_TAG) {
    case kPoint: {
      IdaPoint point = point_from_json(nlohmann::json::parse(text));
      journal.append(to_json(point));
      progress.run_finished(point);
      record_points.at(static_cast<std::size_t>(point.record))
          .emplace(point.intensity, std::move(point));
      continue;
    }
    case kDone: {
      // the record's trace: its intensities, each either from the journal or just sent
      const nlohmann::json done = nlohmann::json::parse(text);
      const auto record = done.at("record").get<std::size_t>();
      const auto intensities = done.at("intensities").get<std::vector<double>>();
      for (const double intensity : intensities)
        points.push_back(record_points.at(record).at(intensity));
      progress.record_finished(intensities.size());
      break;
    }
    case kError:
      if (failure.empty())
        failure = "MPI rank " + std::to_string(worker) + ": " + text;
      break;
    case kReady:
      break;
    default:
      throw std::logic_error("unexpected MPI message tag " + std::to_string(status.MPI_TAG));
    }
    // the worker is free: the next record, or stop
    if (failure.empty() && next_record < study.record_count()) {
      const nlohmann::json task = {{"record", next_record},
                                   {"known", [&] {
                                      nlohmann::json entries = nlohmann::json::array();
                                      for (const auto& [intensity, point] : known[next_record])
                                        entries.push_back(to_json(point));
                                      return entries;
                                    }()}};
      send_text(task.dump(), worker, kTask);
      ++next_record;
    } else {
      send_text("", worker, kStop);
      --working;
    }
  }
  if (!failure.empty())
    throw std::runtime_error(failure);
  return sorted_points(std::move(points));
}

void run_worker(const Session&, const IdaStudy& study) {
  send_text("", 0, kReady);
  for (;;) {
    MPI_Status status;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
    const std::string text = receive_text(status);
    if (status.MPI_TAG == kStop)
      return;
    try {
      const nlohmann::json task = nlohmann::json::parse(text);
      const auto record = task.at("record").get<std::size_t>();
      std::map<double, IdaPoint> known;
      for (const nlohmann::json& entry : task.at("known")) {
        IdaPoint point = point_from_json(entry);
        known.emplace(point.intensity, std::move(point));
      }
      const std::vector<IdaPoint> traced = study.trace(record, known, [](const IdaPoint& point) {
        send_text(to_json(point).dump(), 0, kPoint);
      });
      nlohmann::json intensities = nlohmann::json::array();
      for (const IdaPoint& point : traced)
        intensities.push_back(point.intensity);
      send_text(nlohmann::json{{"record", record}, {"intensities", intensities}}.dump(), 0, kDone);
    } catch (const std::exception& error) {
      send_text(error.what(), 0, kError);
    }
  }
}

#endif

} // namespace brb::ida::mpi
