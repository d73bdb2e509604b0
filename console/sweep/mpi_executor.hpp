#pragma once
// Sweeps across machines with MPI (`mpirun -n N stride sweep <file>`, or Slurm's `srun`): rank 0
// coordinates and runs walks on its own core too; every other rank runs the walks rank 0 hands
// it, one at a time, and sends each row back as the framework's binary encoding. Each rank runs
// its walks in a forked child, so a walk that kills its process costs that run one retry, not
// the rank. MPI is optional at build time: without it these say how to get it.
#include <memory>
#include <string>

#include "console/sweep/executor.hpp"

namespace stride::sweep {

// True when mpirun, mpiexec or srun started this process (their environment variables).
bool started_by_mpi_launcher();
// Whether this binary was built with MPI.
bool mpi_built();
// What to install when it was not.
std::string mpi_missing_text();

class MpiSession {
 public:
  MpiSession();   // MPI_Init; throws stride::Error (with mpi_missing_text()) without MPI
  ~MpiSession();  // MPI_Finalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
};

// Rank 0's executor: its own forked worker plus one slot per other rank.
std::unique_ptr<Executor> mpi_coordinator(MpiSession& session);
// Every other rank: runs what rank 0 sends until it says stop.
void mpi_worker(MpiSession& session, const RunFunction& run);
// Rank 0's `text` to every rank (collective: every rank calls it, between sweeps); the others'
// argument is ignored. A search tells its ranks each generation's sweep this way.
std::string mpi_broadcast(MpiSession& session, const std::string& text);

}  // namespace stride::sweep
