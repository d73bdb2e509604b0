// `stride experiment --set Module.field=value`: parsed strictly, put ahead of an experiment's own
// settings (the sweep file's value wins), and a bad module or field is an error naming the scene.
#include <algorithm>

#include <gtest/gtest.h>

#include "console/cli/arguments.hpp"
#include "console/experiments/parameter_overrides.hpp"
#include "console/experiments/walk_recording.hpp"
#include "console/sweep/sweep_request.hpp"
#include "robot/core/error.hpp"
#include "tests/error_text.hpp"

namespace stride::experiments {
namespace {

using stride::test_support::error_of;

TEST(ParameterOverrides, SplitsModuleFromFieldAndValue) {
  const auto [module, text] =
      parse_parameter_override("TorsoStateEstimator.q_diagonal=[0.1, 0.1, 3e-5, 3e-5]");
  EXPECT_EQ(module, "TorsoStateEstimator");
  EXPECT_EQ(text, "q_diagonal=[0.1, 0.1, 3e-5, 3e-5]");
  EXPECT_EQ(parse_parameter_override("A.b=c.d=e").second, "b=c.d=e");
}

TEST(ParameterOverrides, MalformedTextIsNamed) {
  for (const char* bad : {"", "Module", "Module.field", ".field=1", "Module.=1",
                          "Module.f=", "Module=1.f", "field=1"}) {
    const std::string e = error_of([&] { parse_parameter_override(bad); });
    EXPECT_NE(e.find("--set '" + std::string(bad) + "': expected Module.field=value"),
              std::string::npos)
        << bad << ": " << e;
  }
}

TEST(ParameterOverrides, GoAheadOfTheExperimentsOwnSettings) {
  sweep::SweepRequest r;
  r.file = std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/gains.sweep.xml";
  r.settings = {{"HipStrategy.kp_pitch", "9"}, {"ArmSwing.gain_scale", "1"}};
  const sweep::Sweep s(sweep::request_spec(r), false);
  const std::vector<sweep::Setting>& first = s.plan().runs.at(0).settings;  // hip, K_p 0
  ASSERT_GE(first.size(), 3u);
  EXPECT_EQ(first[0].target, "HipStrategy.kp_pitch");
  EXPECT_EQ(first[0].value, "9");
  EXPECT_EQ(first[1].target, "ArmSwing.gain_scale");
  // The sweep's own kp_pitch comes later, so it is the one the walk keeps.
  const auto own = std::find_if(first.begin() + 2, first.end(), [](const sweep::Setting& x) {
    return x.target == "HipStrategy.kp_pitch";
  });
  ASSERT_NE(own, first.end());
  EXPECT_EQ(own->value, "0");
}

TEST(ParameterOverrides, UnknownFieldFailsBeforeTheWalkNamingSceneAndField) {
  WalkSetup w{std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/hip_slow.xml", 1};
  w.parameters = {{"HipStrategy", "kp=1"}};
  const std::string e = error_of([&] { record_walk(w); });
  EXPECT_NE(e.find("hip_slow.xml: parameters HipStrategy 'kp=1': HipStrategy: no field 'kp'"),
            std::string::npos)
      << e;
}

TEST(ArgumentReaderTexts, EveryRepeatedFlagInOrderAndNothingLeftOver) {
  const std::vector<std::string> args{"posture", "--set", "A.x=1", "--seeds",
                                      "2",       "--set", "B.y=2"};
  cli::ArgumentReader a(args, "experiment");
  EXPECT_EQ(a.texts("--set"), (std::vector<std::string>{"A.x=1", "B.y=2"}));
  EXPECT_EQ(a.unsigned_integer("--seeds"), 2u);
  EXPECT_EQ(a.positional("experiment"), "posture");
  EXPECT_NO_THROW(a.finish());
  EXPECT_TRUE(cli::ArgumentReader(args, "experiment").texts("--out").empty());
  const std::vector<std::string> dangling{"posture", "--set"};
  cli::ArgumentReader b(dangling, "experiment");
  EXPECT_NE(error_of([&] { b.texts("--set"); }).find("--set: expected a value after it"),
            std::string::npos);
}

}  // namespace
}  // namespace stride::experiments
