// `stride` commands refuse bad output paths, absurd durations and huge sweeps before they run,
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

}  // namespace
}  // namespace stride::test_support
