// `stride` commands refuse bad output paths, absurd durations and huge sweeps before they run,
// flag legal but absurd parameters and torques,
// create nothing outside what was named, and quote at most ~80 characters of bad input. Each
// test starts the real program from a temporary folder outside the checkout.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "tests/cli/stride_process.hpp"

namespace stride::test_support {
namespace {

namespace fs = std::filesystem;
const std::string kStand = source_file("scenes/nao_stand.xml");

bool one_line(const std::string& s) {
  return !s.empty() && s.find('\n') == s.size() - 1;
}

TEST(OutputGuards, MissingFoldersAreRefusedBeforeTheRunAndNothingIsCreated) {
  TempFolder dir;
  for (const auto& [flag, path] :
       std::vector<std::pair<std::string, std::string>>{{"--report", "no/such/report.json"},
                                                        {"--snapshot", "no/such/end.png"},
                                                        {"--log", "no/such/run.log"},
                                                        {"--video", "no/such/walk.mp4"},
                                                        {"--video", "no/such/frames"}}) {
    const Finished r = run_stride({"run", kStand, "--seconds", "600", flag, path}, dir.path());
    EXPECT_EQ(r.exit_code, 1) << flag << " " << r.err;
    EXPECT_TRUE(one_line(r.err)) << r.err;
    EXPECT_NE(r.err.find("stride run: " + flag + ": cannot write '" + path + "'"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("folder 'no/such' does not exist"), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "") << "the run started: " << r.out;
    EXPECT_LT(r.seconds, 10.0) << "600 s of simulation were not refused up front";
  }
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"experiment", "posture", "--seeds", "1", "--out", "a/b/c"},
           {"pattern", "--preset", "medium", "--csv", "x/p.csv"},
           {"pattern", "--preset", "medium", "--csv", "p.csv", "--plots", "x/y"},
           {"swing-leg", "planar-step", "--plots", "x/y"},
           {"landing", "--csv", "x/landing.csv"},
           {"balance", "lqr", "--plots", "x/y"}}) {
    const Finished r = run_stride(args, dir.path());
    EXPECT_NE(r.exit_code, 0) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << args[0] << ": " << r.err;
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{}) << "a refused command created files";
}

TEST(OutputGuards, OnlyTheNamedFolderIsCreated) {
  TempFolder dir;
  fs::create_directory(dir / "results");
  const Finished r = run_stride(
      {"run", kStand, "--seconds", "0.1", "--video", "results/frames", "--fps", "20"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"results", "results/frames",
                                                     "results/frames/frame_000000.png",
                                                     "results/frames/frame_000001.png"}));
  // A file where a folder is wanted, a folder where a file is wanted.
  const Finished f = run_stride({"run", kStand, "--report", "results"}, dir.path());
  EXPECT_NE(f.err.find("--report: cannot write 'results': it is a folder"), std::string::npos)
      << f.err;
}

TEST(Caps, SecondsAndSweepRangesHaveCapsWithAClearMessage) {
  TempFolder dir;
  const Finished run = run_stride({"run", kStand, "--seconds", "1e7"}, dir.path());
  EXPECT_EQ(run.exit_code, 2);  // a usage error
  EXPECT_EQ(run.err, "stride run: --seconds: 1e+07 s outside [0, 1e+06]\n");
  const Finished swing = run_stride({"swing-leg", "planar-step", "--seconds", "2e6"}, dir.path());
  EXPECT_NE(swing.err.find("stride swing-leg: --seconds: 2e+06 s outside [0, 1e+06]"),
            std::string::npos)
      << swing.err;
  const Finished sweep =
      run_stride({"push-sweep", "--scene", source_file("scenes/push/stand_balance.xml"),
                  "--impulses", "0:100:0.001"},
                 dir.path());
  EXPECT_NE(sweep.err.find("--impulses: '0:100:0.001' has more than 2000 values"),
            std::string::npos)
      << sweep.err;
  EXPECT_LT(sweep.seconds, 10.0);
}

TEST(ErrorText, LongInputIsQuotedInAboutEightyCharacters) {
  TempFolder dir;
  const std::string pasted(400, '9');
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"run", kStand, "--seconds", pasted + "s"},
           {"run", kStand, "--set", "Stand." + pasted},
           {"experiment", pasted},
           {"-c", "get representation:" + pasted, source_file("scenes/nao_stand_controlled.xml")},
           {"kin", "fk", "--chain", "lleg", "--q", pasted + "x 0 0 0 0 0"}}) {
    const Finished r = run_stride(args, dir.path());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_TRUE(one_line(r.err)) << r.err;
    EXPECT_EQ(r.err.find(std::string(81, '9')), std::string::npos) << r.err;
    EXPECT_LT(r.err.size(), 240u) << r.err;
    EXPECT_NE(r.err.find("characters)"), std::string::npos) << r.err;
  }
}

TEST(Plausibility, ALegalButAbsurdStrideIsFlagged) {
  TempFolder dir;
  const Finished ok = run_stride({"pattern", "--preset", "medium", "--csv", "p.csv"}, dir.path());
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.out.find("note:"), std::string::npos) << ok.out;
  const Finished fast = run_stride(
      {"pattern", "--preset", "medium", "--set", "T_stride=0.01", "--csv", "p.csv"}, dir.path());
  EXPECT_NE(fast.out.find("note: T_stride = 0.01 s: no NAO strides that fast"), std::string::npos)
      << fast.out << fast.err;
}

// `stride run` flags legal but absurd module parameters before it runs, one note each, and says
// nothing about the shipped scenes' own values.
TEST(Plausibility, AbsurdParametersOfARunAreFlagged) {
  TempFolder dir;
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"scenes/walking/open_loop_medium.xml", "PatternWalk.T_stride=0.01"},
       "note: PatternWalk: T_stride = 0.01 s: no NAO strides that fast"},
      {{"scenes/swing_leg/hanging_nao.xml", "SwingLegTracking.kd=500"},
       "note: SwingLegTracking: lambda = 20 1/s, kd = 500 N m s/rad: an error of 0.1 rad and 1 "
       "rad/s asks for 1500 N m, 115 x the largest NAO joint's stall torque (13.1 N m;"},
      {{"scenes/push/stand_balance.xml", "AnkleBalance.kp=10000"},
       "note: AnkleBalance: kp = 10000 1/s^2: a closed-loop frequency of 100 rad/s, faster than a "
       "10 ms control loop follows (plausible up to 2500; Fig. 7.5 uses 72)"},
      {{"scenes/experiments/hip_medium.xml", "HipStrategy.kd_roll=-0.9"},
       "note: HipStrategy: kd_roll = -0.9 s: plausible |kd| up to 0.3 s"}};
  for (const auto& [scene_and_set, note] : cases) {
    const std::string scene = source_file(scene_and_set[0]);
    const Finished plain = run_stride({"run", scene, "--seconds", "0.01"}, dir.path());
    ASSERT_EQ(plain.exit_code, 0) << plain.err;
    EXPECT_EQ(plain.out.find("note:"), std::string::npos) << plain.out;
    const Finished absurd =
        run_stride({"run", scene, "--seconds", "0.01", "--set", scene_and_set[1]}, dir.path());
    ASSERT_EQ(absurd.exit_code, 0) << absurd.err;
    EXPECT_NE(absurd.out.find(note), std::string::npos) << absurd.out;
  }
}

// The swing-leg study's App. C leg at the thesis' gains (lambda 200, K_D 100) asks for 20 kN m at
// the step's start: the figure is printed with its ratio to what a NAO motor gives.
TEST(Plausibility, ASwingLegTorqueOfTwentyKilonewtonMetresIsFlagged) {
  TempFolder dir;
  const Finished r = run_stride(
      {"swing-leg", "planar-step", "--controller", "pd", "--seconds", "0.05"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("max |tau| 20944.0 N m  (!) 1.6e+03 x the largest NAO joint's stall "
                       "torque (13.1 N m)"),
            std::string::npos)
      << r.out;
}

}  // namespace
}  // namespace stride::test_support
