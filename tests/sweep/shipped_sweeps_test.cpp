// Every sweep file shipped under scenes/ (the thesis studies and the new ones) parses, names
// known keys, columns and setting targets, and its scenes load with each first run's settings:
// what `stride sweep` checks before any run, so a broken study shows here.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/sweep/sweep_parser.hpp"
#include "console/sweep/tally.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_sweeps() {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(STRIDE_SOURCE_DIR) / "scenes"))
    if (e.path().filename().string().ends_with(".sweep.xml")) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ShippedSweeps, EveryOneParsesAndItsScenesLoad) {
  const auto files = shipped_sweeps();
  // posture, knee-energy, gains, fastest, arm-swing, push, push-walk
  EXPECT_GE(files.size(), 7u);
  for (const fs::path& p : files) {
    SCOPED_TRACE(p.string());
    try {
      const Sweep s(parse_sweep_file(p.string()));
      const Tallies t(s);
      EXPECT_GT(s.plan().runs.size(), 0u);
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

}  // namespace
}  // namespace stride::sweep
