// Two `stride sweep --resume` on one output folder at once: the second finds the folder locked
// (flock on <out>/.lock), says so in one line naming the first one's pid and runs nothing; the
// first completes with every run once in runs.csv and timing.csv.
#include <signal.h>

#include <set>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "tests/child_process.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using stride::test_support::read_text;

const std::string kStride = std::string(STRIDE_BINARY_DIR) + "/stride";
const std::string kSweep = std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/data/stand.sweep.xml";

// The first column of every data row.
std::multiset<std::string> run_ids(const fs::path& csv) {
  std::istringstream in(read_text(csv));
  std::multiset<std::string> ids;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) ids.insert(line.substr(0, line.find(',')));
  return ids;
}

TEST(SweepLock, SecondResumeOnOneFolderIsRefusedInOneLine) {
  const fs::path dir = stride::test_support::fresh_path("faults", "sweep_lock");
  const pid_t first =
      stride::test_support::start_process({kStride, "sweep", kSweep, "--quiet", "--jobs", "1",
                                           "--seeds", "20", "--resume", "--out", dir.string()},
                                          dir.string() + ".first.out", dir.string() + ".first.err");
  // Wait (bounded) until the first holds the folder: its manifest is written after the lock.
  for (int i = 0; i < 600 && !fs::exists(dir / "manifest.txt"); ++i)
    std::this_thread::sleep_for(50ms);
  ASSERT_TRUE(fs::exists(dir / "manifest.txt")) << read_text(dir.string() + ".first.err");
  const pid_t second = stride::test_support::start_process(
      {kStride, "sweep", kSweep, "--quiet", "--jobs", "1", "--seeds", "20", "--resume", "--out",
       dir.string()},
      dir.string() + ".second.out", dir.string() + ".second.err");
  const int second_code = stride::test_support::finish_process(second);
  const std::string err = read_text(dir.string() + ".second.err");
  EXPECT_EQ(second_code, 1) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_NE(err.find("'" + dir.string() + "' is in use by another sweep (pid " +
                     std::to_string(first) + ","),
            std::string::npos)
      << err;
  ASSERT_EQ(stride::test_support::finish_process(first), 0)
      << read_text(dir.string() + ".first.err");
  // 40 runs (2 iteration settings x 20 seeds, one at a time: long enough to overlap), each once
  // in both files.
  const auto runs = run_ids(dir / "runs.csv"), timing = run_ids(dir / "timing.csv");
  EXPECT_EQ(runs.size(), 40u);
  EXPECT_EQ(timing.size(), 40u) << read_text(dir / "timing.csv");
  EXPECT_EQ(std::set<std::string>(timing.begin(), timing.end()).size(), 40u);
  // The lock goes with its holder: a third --resume after the first ended is welcome.
  EXPECT_EQ(stride::test_support::finish_process(stride::test_support::start_process(
                {kStride, "sweep", kSweep, "--quiet", "--jobs", "1", "--seeds", "20", "--resume",
                 "--out", dir.string()},
                dir.string() + ".third.out", dir.string() + ".third.err")),
            0)
      << read_text(dir.string() + ".third.err");
  fs::remove_all(dir);
}

}  // namespace
