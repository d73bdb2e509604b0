// `stride balance ...` end to end: outputs, files, and one-line errors with exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "console/cli/subcommand.hpp"

namespace stride::cli {
int balance_main(Args args, std::ostream& out, std::ostream& err);

namespace {

struct Result {
  int code;
  std::string out, err;
};

Result run(std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = balance_main(args, out, err);
  return {code, out.str(), err.str()};
}

TEST(BalanceCli, ClassifyPrintsStrategyAndBoundaries) {
  const Result r = run({"classify", "--x0", "0.02", "--v0", "0.4"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("strategy: ankle"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[-0.056, 0.103]"), std::string::npos) << r.out;
  const Result j = run({"classify", "--v0", "0.8", "--json"});
  EXPECT_EQ(j.code, 0) << j.err;
  EXPECT_EQ(j.out.front(), '{');
  EXPECT_NE(j.out.find("\"strategy\": \"combined\""), std::string::npos) << j.out;
}

TEST(BalanceCli, ClosedLoopReportsTheFig77Cases) {
  const Result r = run({"closed-loop", "--kp", "72", "--kd", "12", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"x0\": -0.4, \"v0\": 2.3, \"converged\": true"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"x0\": -0.32, \"v0\": 2.3, \"converged\": false"), std::string::npos);
}

TEST(BalanceCli, HipWritesLongCsv) {
  const std::string path =
      (std::filesystem::temp_directory_path() / "stride_balance_hip_test.csv").string();
  const Result r = run({"hip", "--x0", "-0.1", "--v0", "0.7", "--duration", "0.5", "--csv", path});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("recoverable"), std::string::npos);
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "case,t,x,v,theta,theta_dot,tau,zmp");
  int lines = 0;
  for (std::string l; std::getline(in, l);) ++lines;
  EXPECT_EQ(lines, 501);  // 0 .. 0.5 s at 1 ms
  std::filesystem::remove(path);
}

TEST(BalanceCli, BadArgumentsAreOneLineErrorsWithExitCode2) {
  for (const auto& args : std::vector<std::vector<std::string>>{{"classify", "--v0", "fast"},
                                                                {"classify", "--bogus", "1"},
                                                                {"hip", "--x0"},
                                                                {"wobble"},
                                                                {},
                                                                {"lqr", "--q", "1,2,3"},
                                                                {"hip", "--tau-b", "5"},
                                                                {"closed-loop", "--x0", "0.1"}}) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_NE(run({"classify", "--v0", "fast"}).err.find("--v0"), std::string::npos);
  EXPECT_NE(run({"hip", "--tau-b", "5"}).err.find("tau_backward"), std::string::npos);
}

}  // namespace
}  // namespace stride::cli
