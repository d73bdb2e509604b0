// Built when CMake found no MPI: the sweep still runs locally; MPI use says how to get it.
#include "console/sweep/mpi_executor.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {

bool mpi_built() {
  return false;
}

MpiSession::MpiSession() {
  throw Error(mpi_missing_text());
}
MpiSession::~MpiSession() = default;

std::unique_ptr<Executor> mpi_coordinator(MpiSession&) {
  throw Error(mpi_missing_text());
}
void mpi_worker(MpiSession&, const RunFunction&) {
  throw Error(mpi_missing_text());
}
std::string mpi_broadcast(MpiSession&, const std::string&) {
  throw Error(mpi_missing_text());
}

}  // namespace stride::sweep
