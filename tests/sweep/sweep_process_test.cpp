// `stride sweep` as a lab runs it, through the real binary: a bad sweep file is one line and
// runs nothing; kill -9 of a worker mid-run and kill -9 of the whole sweep then --resume leave
// the same runs.csv as an uninterrupted sweep, with no run made twice; Ctrl-C leaves a resumable
// output; `mpirun -n 3` gives the rows --jobs 1 and --jobs 2 give, byte for byte.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/child_process.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string kStride = std::string(STRIDE_BINARY_DIR) + "/stride";
const std::string kSweep = std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/data/stand.sweep.xml";

constexpr auto read = &stride::test_support::read_text;
constexpr auto start = &stride::test_support::start_process;
constexpr auto finish = &stride::test_support::finish_process;

fs::path fresh(const std::string& name) {
  return stride::test_support::fresh_path("sweepcli", name);
}

int run(const std::vector<std::string>& args, const fs::path& dir) {
  return finish(start(args, dir.string() + ".out", dir.string() + ".err"));
}

int data_rows(const fs::path& csv) {
  const std::string t = read(csv);
  return static_cast<int>(std::count(t.begin(), t.end(), '\n')) - 1;
}

// Waits (at most 60 s) until the sweep's runs.csv has `n` rows.
bool wait_rows(const fs::path& dir, int n) {
  for (int i = 0; i < 600; ++i) {
    if (fs::exists(dir / "runs.csv") && data_rows(dir / "runs.csv") >= n) return true;
    std::this_thread::sleep_for(100ms);
  }
  return false;
}

std::vector<pid_t> children(pid_t pid) {
  std::istringstream in(
      read("/proc/" + std::to_string(pid) + "/task/" + std::to_string(pid) + "/children"));
  std::vector<pid_t> out;
  for (pid_t c; in >> c;) out.push_back(c);
  return out;
}

// How many times each run id appears in timing.csv (each made run is listed once).
std::map<int, int> made(const fs::path& dir) {
  std::istringstream in(read(dir / "timing.csv"));
  std::map<int, int> m;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) ++m[std::stoi(line)];
  return m;
}

class SweepProcess : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    reference_ = fresh("reference");
    ASSERT_EQ(
        run({kStride, "sweep", kSweep, "--jobs", "1", "--quiet", "--out", reference_}, reference_),
        0)
        << read(reference_.string() + ".err");
  }
  static std::string reference() { return read(reference_ / "runs.csv"); }
  static fs::path reference_;
};
fs::path SweepProcess::reference_;

TEST_F(SweepProcess, ReferenceHasEveryRunAndTheTally) {
  EXPECT_EQ(data_rows(reference_ / "runs.csv"), 6);
  const std::string out = read(reference_.string() + ".out");
  EXPECT_NE(out.find("iterations  runs"), std::string::npos) << out;
  EXPECT_NE(read(reference_ / "manifest.txt").find("revision: "), std::string::npos);
  EXPECT_EQ(read(reference_ / "sweep.xml"), read(kSweep));
}

TEST_F(SweepProcess, BadSweepFileIsOneLineAndRunsNothing) {
  const fs::path dir = fresh("bad");
  fs::create_directories(dir);
  std::ofstream(dir / "bad.xml")
      << "<sweep>\n<scene file=\"x.xml\"/>\n<run secnds=\"1\"/>\n</sweep>\n";
  EXPECT_EQ(
      run({kStride, "sweep", (dir / "bad.xml").string(), "--out", (dir / "out").string()}, dir), 3);
  EXPECT_EQ(read(dir.string() + ".err"),
            (dir / "bad.xml").string() +
                ":3: <run>: unknown attribute 'secnds' (expected seconds, until)\n");
  EXPECT_FALSE(fs::exists(dir / "out"));
  fs::remove_all(dir);
}

TEST_F(SweepProcess, KillNineOfTheSweepThenResumeMakesEachRunOnce) {
  const fs::path dir = fresh("killed");
  const pid_t pid = start({kStride, "sweep", kSweep, "--jobs", "2", "--quiet", "--out", dir},
                          dir.string() + ".out", dir.string() + ".err");
  ASSERT_TRUE(wait_rows(dir, 3));
  ::kill(-pid, SIGKILL);  // the sweep and its workers
  finish(pid);
  const int before = data_rows(dir / "runs.csv");
  ASSERT_LT(before, 6);
  EXPECT_EQ(
      run({kStride, "sweep", kSweep, "--jobs", "2", "--quiet", "--resume", "--out", dir}, dir), 0)
      << read(dir.string() + ".err");
  EXPECT_EQ(read(dir / "runs.csv"), reference());
  const auto m = made(dir);
  EXPECT_EQ(m.size(), 6u);
  for (const auto& [id, n] : m) EXPECT_EQ(n, 1) << "run " << id;
  fs::remove_all(dir);
}

TEST_F(SweepProcess, KillNineOfAWorkerMidRunCostsOneRetry) {
  const fs::path dir = fresh("worker");
  const pid_t pid = start({kStride, "sweep", kSweep, "--jobs", "2", "--quiet", "--out", dir},
                          dir.string() + ".out", dir.string() + ".err");
  ASSERT_TRUE(wait_rows(dir, 1));
  std::vector<pid_t> workers;
  for (int i = 0; i < 100 && workers.empty(); ++i, std::this_thread::sleep_for(20ms))
    workers = children(pid);
  ASSERT_FALSE(workers.empty());
  ::kill(workers[0], SIGKILL);
  EXPECT_EQ(finish(pid), 0) << read(dir.string() + ".err");
  EXPECT_EQ(read(dir / "runs.csv"), reference());
  EXPECT_NE(read(dir / "timing.csv").find(",2,"), std::string::npos) << "a retried run";
  fs::remove_all(dir);
}

TEST_F(SweepProcess, CtrlCLeavesAResumableOutput) {
  const fs::path dir = fresh("interrupted");
  const pid_t pid = start({kStride, "sweep", kSweep, "--jobs", "2", "--quiet", "--out", dir},
                          dir.string() + ".out", dir.string() + ".err");
  ASSERT_TRUE(wait_rows(dir, 2));
  ::kill(pid, SIGINT);
  EXPECT_EQ(finish(pid), 130);
  EXPECT_NE(read(dir.string() + ".out").find("continue with --resume"), std::string::npos);
  EXPECT_EQ(run({kStride, "sweep", kSweep, "--quiet", "--resume", "--out", dir}, dir), 0);
  EXPECT_EQ(read(dir / "runs.csv"), reference());
  fs::remove_all(dir);
}

TEST_F(SweepProcess, MpirunThreeRanksGivesTheSameRows) {
  if (::system("command -v mpirun > /dev/null") != 0) GTEST_SKIP() << "no mpirun";
  const fs::path dir = fresh("mpi");
  const int code = run(
      stride::test_support::under_mpirun(3, {kStride, "sweep", kSweep, "--quiet", "--out", dir}),
      dir);
  const std::string err = read(dir.string() + ".err");
  if (err.find("built without MPI") != std::string::npos) GTEST_SKIP() << err;
  ASSERT_EQ(code, 0) << err;
  EXPECT_EQ(read(dir / "runs.csv"), reference());
  std::set<std::string> workers;
  std::istringstream in(read(dir / "timing.csv"));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) workers.insert(line.substr(line.rfind(',') + 1));
  EXPECT_EQ(workers.size(), 3u) << "every rank ran walks";
  fs::remove_all(dir);
}

}  // namespace
