// Ctrl-C during `stride run`: the real process gets SIGINT, stops between physics steps, writes
// the report of what ran and exits 130; meanwhile its progress line comes as plain periodic
// lines because stderr is not a terminal.
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <thread>

#include "tests/cli/stride_process.hpp"
#include "tests/json_reader.hpp"

namespace stride::test_support {
namespace {

TEST(Interrupt, CtrlCWritesTheReportOfWhatRan) {
  TempFolder dir;
  StrideProcess p(
      {"run", source_file("scenes/nao_stand.xml"), "--seconds", "3000", "--report", "report.json"},
      dir.path(), {{"STRIDE_PROGRESS", "plain:0.3"}});
  // Wait for two progress lines: the run is under way.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  for (std::string err = p.err_so_far(); std::count(err.begin(), err.end(), '\n') < 2;
       err = p.err_so_far()) {
    ASSERT_LT(std::chrono::steady_clock::now(), deadline) << "no progress lines: " << err;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  p.signal(SIGINT);
  const Finished f = p.wait();
  EXPECT_EQ(f.exit_code, 130) << f.err;

  // Plain progress lines: simulated seconds of 3000, percentage, elapsed, speed-up, ETA.
  const std::regex line(
      R"(run: [0-9]+\.[0-9]/3000\.0 s \([0-9]+ %\), [0-9]+ s, [0-9.]+x real time, ETA [0-9hmins ]+)");
  std::istringstream lines(f.err);
  int progress_lines = 0;
  for (std::string l; std::getline(lines, l);) {
    EXPECT_TRUE(std::regex_match(l, line)) << l;
    ++progress_lines;
  }
  EXPECT_GE(progress_lines, 2);
  EXPECT_EQ(f.err.find('\r'), std::string::npos) << "terminal redraws in a plain log";

  // The report covers the run up to the interrupt.
  EXPECT_NE(f.out.find("interrupted at "), std::string::npos) << f.out;
  std::ifstream in(dir / "report.json");
  ASSERT_TRUE(in) << "no report after Ctrl-C";
  const Json report = JsonReader::parse(std::string(std::istreambuf_iterator<char>(in), {}));
  EXPECT_EQ(report["interrupted"].boolean(), true);
  EXPECT_EQ(report["requested_time"].number(), 3000.0);
  const double ran = report["sim_time"].number();
  EXPECT_GT(ran, 0.0);
  EXPECT_LT(ran, 3000.0);
  EXPECT_EQ(std::llround(report["physics_steps"].number()), std::llround(ran / 0.001));
  EXPECT_EQ(report["state_hash"].text().size(), 16u);
}

TEST(Progress, AShortRunPrintsNoProgressAndQuietPrintsNone) {
  TempFolder dir;
  const Finished short_run =
      run_stride({"run", source_file("scenes/nao_stand.xml"), "--seconds", "0.2"}, dir.path(),
                 {{"STRIDE_PROGRESS", "plain"}});
  EXPECT_EQ(short_run.exit_code, 0);
  EXPECT_EQ(short_run.err, "");
  const Finished bad = run_stride({"run", source_file("scenes/nao_stand.xml"), "--seconds", "0.2"},
                                  dir.path(), {{"STRIDE_PROGRESS", "fancy"}});
  EXPECT_EQ(bad.err, "STRIDE_PROGRESS: expected tty, plain, plain:<seconds> or off, got 'fancy'\n");
}

}  // namespace
}  // namespace stride::test_support
