// A build without MPI: the sweep's MPI entry points refuse with the text that says what to
// install, and the launcher check still reads mpirun's environment (so `mpirun stride sweep`
// on such a build is told, not run once per rank).
#include <gtest/gtest.h>

#include <cstdlib>

#include "console/sweep/mpi_executor.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

TEST(SweepWithoutMpi, SaysItWasBuiltWithoutMpi) {
  EXPECT_FALSE(mpi_built());
}

TEST(SweepWithoutMpi, MpiSessionRefusesWithInstallHint) {
  try {
    MpiSession session;
    FAIL() << "an MPI session started in a build without MPI";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), mpi_missing_text());
    EXPECT_NE(mpi_missing_text().find("apt-get install libopenmpi-dev openmpi-bin"),
              std::string::npos);
    EXPECT_NE(mpi_missing_text().find("--jobs N"), std::string::npos);
  }
}

TEST(SweepWithoutMpi, LauncherEnvironmentIsStillRecognised) {
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::unsetenv("PMI_SIZE");
  ::unsetenv("PMIX_RANK");
  ::unsetenv("MPI_LOCALNRANKS");
  EXPECT_FALSE(started_by_mpi_launcher());
  ::setenv("OMPI_COMM_WORLD_SIZE", "2", 1);
  EXPECT_TRUE(started_by_mpi_launcher());
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::setenv("PMI_SIZE", "4", 1);  // Slurm's srun
  EXPECT_TRUE(started_by_mpi_launcher());
  ::unsetenv("PMI_SIZE");
}

}  // namespace
}  // namespace stride::sweep
