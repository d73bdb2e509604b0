#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "console/cli/subcommand.hpp"
#include "tests/json_reader.hpp"

namespace stride::cli {

int kin_main(Args args, std::ostream& out, std::ostream& err);
int dyn_main(Args args, std::ostream& out, std::ostream& err);

namespace {

using test_support::Json;
using test_support::JsonReader;

struct CliRun {
  int code;
  std::string out, err;
};

CliRun run(int (*main)(Args, std::ostream&, std::ostream&), std::vector<std::string> args) {
  std::ostringstream out, err;
  const int code = main(args, out, err);
  return {code, out.str(), err.str()};
}

const std::string kUrdf = STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf";

TEST(KinCli, ForwardKinematicsOfTheZeroLeg) {
  const CliRun r = run(kin_main, {"fk", "--chain", "lleg", "--q", "0 0 0 0 0 0", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  const Json j = JsonReader::parse(r.out);  // the one JSON writer's output parses
  EXPECT_NEAR(j["position"][0].number(), 0.0, 1e-9) << r.out;
  EXPECT_NEAR(j["position"][1].number(), 0.050, 1e-9) << r.out;
  EXPECT_NEAR(j["position"][2].number(), -0.33309, 1e-6) << r.out;
  EXPECT_EQ(j["rpy"].size(), 3u);
}

TEST(KinCli, InverseKinematicsRoundTrip) {
  const CliRun r = run(kin_main, {"ik", "--chain", "rleg", "--pose", "0 -0.05 -0.33309 0 0 0"});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("RKneePitch      0.000000\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("reachable: yes"), std::string::npos) << r.out;
}

TEST(KinCli, CentreOfMassByJointNames) {
  const CliRun r = run(kin_main, {"com", "--q", "LKneePitch=0.5 RKneePitch=0.5", "--urdf", kUrdf});
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("total mass (kg): 5.305350"), std::string::npos) << r.out;
}

TEST(KinCli, BadArgumentsGiveOneLineNamingTheArgumentAndExitTwo) {
  const std::vector<std::vector<std::string>> bad = {
      {"fk", "--chain", "leg", "--q", "0"},
      {"fk", "--chain", "lleg", "--q", "0 0 0"},
      {"fk", "--chain", "lleg", "--q", "0 0 x 0 0 0"},
      {"ik", "--chain", "lleg"},
      {"com", "--q", "Elbow=1"},
      {"fk", "--frobnicate", "1"},
      {"walk"}};
  const char* names[] = {"--chain", "--q", "--q", "--pose", "--q", "--frobnicate", "walk"};
  for (size_t i = 0; i < bad.size(); ++i) {
    const CliRun r = run(kin_main, bad[i]);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.err.find(names[i]), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  }
}

TEST(DynCli, ParameterVectorsNextToTheThesis) {
  const CliRun planar = run(dyn_main, {"params", "--model", "planar"});
  EXPECT_EQ(planar.code, 0);
  EXPECT_NE(planar.out.find("a7  G1  0.649997      thesis 0.650"), std::string::npos) << planar.out;
  const CliRun spatial = run(dyn_main, {"params", "--model", "3d", "--json"});
  EXPECT_EQ(spatial.code, 0);
  const Json j = JsonReader::parse(spatial.out);
  EXPECT_EQ(j["model"].text(), "3d");
  EXPECT_NEAR(j["a"][0].number(), 0.00112796, 5e-9) << spatial.out;
  EXPECT_EQ(j["thesis"][14].number(), 0.65);  // J15 as the thesis prints it
  EXPECT_EQ(j["a"].size(), 17u);
  const CliRun bad = run(dyn_main, {"params", "--model", "4d"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--model"), std::string::npos);
}

}  // namespace
}  // namespace stride::cli
