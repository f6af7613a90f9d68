// Distributed IDA with MPI (built with -DBRB_WITH_MPI=ON): a master/worker scheme with dynamic
// load balancing. Rank 0 (the master) holds the journal, hands one record at a time to the
// next worker that asks, appends every point the workers send to the journal and writes the
// outputs; the workers trace their records (the same IdaStudy::trace as the threads) and
// send each finished run at once, so a killed job loses at most the runs in progress. The
// points are the same as those of the threaded run: each run depends only on its record and
// intensity.
#pragma once

#include "brb/ida/ida_run.hpp"

#include <functional>
#include <map>
#include <vector>

namespace brb::ida::mpi {

/// Whether this build has MPI.
bool available();

/// Whether the process was started by an MPI launcher with more than one rank (read from
/// the launcher's environment: OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_SIZE).
bool launched_with_several_ranks();

/// MPI_Init_thread / MPI_Finalize for the lifetime of the object (only with MPI).
class Session {
public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

  /// Rank 0 calls it with its verdict after opening the journal; every rank returns it
  /// (MPI_Bcast): the workers stop when the master could not start.
  bool broadcast_go(bool go) const;

private:
  int rank_ = 0;
  int size_ = 1;
};

/// The master's side (rank 0, at least one worker): returns every point sorted by (record,
/// intensity). A worker's error stops the hand-out; it is rethrown once every worker stopped.
std::vector<IdaPoint> run_master(const Session& session, const IdaStudy& study, Journal& journal,
                                 const std::vector<std::map<double, IdaPoint>>& known,
                                 IdaProgress& progress);

/// A worker's side (ranks > 0): traces the records the master hands out until told to stop.
void run_worker(const Session& session, const IdaStudy& study);

} // namespace brb::ida::mpi
