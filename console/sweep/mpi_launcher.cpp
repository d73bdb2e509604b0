#include <cstdlib>

#include "console/sweep/mpi_executor.hpp"

namespace stride::sweep {

bool started_by_mpi_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v)) return true;
  return false;
}

std::string mpi_missing_text() {
  return "this stride was built without MPI; install it (Debian: apt-get install libopenmpi-dev "
         "openmpi-bin) and build again, or run the sweep on one machine with --jobs N";
}

}  // namespace stride::sweep
