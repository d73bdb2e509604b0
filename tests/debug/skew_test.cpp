// Revision skew: the robot runs a module and a representation the console was never built with
// (they exist only in this test). `stride --connect` still lists them, shows them and edits them,
// from the type descriptions the robot sends with the values.
#include <thread>

#include <gtest/gtest.h>

#include "tests/debug/robot_loop.hpp"
#include "tests/lola/child_process.hpp"

namespace stride::test {
namespace {

struct SkewParameters {
  STRIDE_FIELDS(SkewParameters);
  STRIDE_FIELD(double, gain) = 1.5;
  STRIDE_FIELD(std::int64_t, mode) = 2;
  static constexpr std::string_view kTypeName = "SkewParameters";
};

struct SkewOutput {
  STRIDE_FIELDS(SkewOutput);
  STRIDE_FIELD(double, y) = 0;
  STRIDE_FIELD(std::int64_t, mode) = 0;
  static constexpr std::string_view kTypeName = "SkewOutput";
};

// SkewOutput = (gain, mode) of its parameters; only this test knows either type.
class SkewModule final : public Module {
 public:
  explicit SkewModule(ModuleContext& c)
      : params_(c.parameters<SkewParameters>()), out_(c.provide<SkewOutput>()) {}
  void update() override {
    out_.y = params_.gain;
    out_.mode = params_.mode;
  }

 private:
  const SkewParameters& params_;
  SkewOutput& out_;
};

TEST(DebugSkew, ConsoleWithoutTheTypesListsShowsAndEditsThemFromTheRobotsDescriptions) {
  ModuleRegistry registry = test_registry();
  registry.add<SkewModule>("SkewModule");
  RuntimeConfig config = test_config();
  config.providers["SkewOutput"] = "SkewModule";
  RobotLoop loop(loopback_options(), 0.01, std::move(registry), config);

  ChildProcess console(
      {STRIDE_BINARY_DIR "/stride", "--connect", loop.endpoint().text(), "-c",
       "mr ?; get module:SkewModule; set module:SkewModule gain=2.25 mode=7; "
       "get module:SkewModule.gain; wait until representation:SkewOutput.mode == 7 "
       "timeout 2; get representation:SkewOutput; set module:SkewModule mode=x"},
      "skew_console");
  ASSERT_EQ(console.wait_for(60), 1) << console.err();
  const std::string out = console.out();
  EXPECT_NE(out.find("SkewOutput"), std::string::npos) << out;  // listed with its provider
  EXPECT_NE(out.find("SkewModule"), std::string::npos) << out;
  EXPECT_NE(out.find("{gain=1.5, mode=2}\n"), std::string::npos) << out;
  EXPECT_NE(out.find("\n2.25\n"), std::string::npos) << out;
  EXPECT_NE(out.find("{y=2.25, mode=7}\n"), std::string::npos) << out;
  // A bad edit of a type the console does not know: one line naming the field, nothing changed.
  EXPECT_NE(console.err().find("mode"), std::string::npos) << console.err();
  EXPECT_EQ(console.err().find('\n'), console.err().size() - 1) << console.err();
  loop.stop();
  EXPECT_EQ(loop.runtime().get("module:SkewModule.mode"), "7");
}

}  // namespace
}  // namespace stride::test
