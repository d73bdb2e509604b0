// SimRobot conventions on the Runtime: `set representation:X` holds every frame until
// `unchanged`; debug requests print, plot and stop; every module's parameters with their ranges.
#include <gtest/gtest.h>

#include "robot/runtime/runtime.hpp"
#include "tests/error_text.hpp"
#include "tests/framework/fake_link.hpp"

namespace stride {
namespace {

using test::FakeLink;
using test_support::error_of;

const int kHeadYaw = hal::index(hal::JointId::HeadYaw);

TEST(Override, HoldsEveryFrameAgainstItsProviderUntilUnchanged) {
  const auto registry = test::test_registry();
  FakeLink link;
  Runtime rt(registry, test::test_config(), link);
  rt.step();
  const double stand_head = rt.representation<JointRequest>().position[kHeadYaw];
  rt.set("representation:JointRequest", "position[HeadYaw]=0.4");
  rt.set("representation:Counter", "n=7");
  EXPECT_EQ(rt.get("representation:JointRequest.position[HeadYaw]"), "0.4");  // at once
  for (int frame = 0; frame < 100; ++frame) {
    ASSERT_TRUE(rt.step());
    // The provider wrote its own value; the override replaced it before anyone read it.
    ASSERT_EQ(rt.representation<JointRequest>().position[kHeadYaw], 0.4) << frame;
    ASSERT_EQ(link.last.position[kHeadYaw], 0.4) << frame;
    ASSERT_EQ(rt.representation<test::Doubled>().n, 14) << frame;  // its consumer sees it
  }
  EXPECT_EQ(rt.overrides().at("JointRequest"), "position[HeadYaw]=0.4");
  rt.set("representation:JointRequest", "position[HeadPitch]=0.1");  // adds to what is held
  EXPECT_EQ(rt.overrides().at("JointRequest"), "position[HeadYaw]=0.4 position[HeadPitch]=0.1");
  rt.set("representation:JointRequest", "unchanged");
  rt.set("representation:Counter", "unchanged");
  EXPECT_TRUE(rt.overrides().empty());
  rt.step();
  EXPECT_EQ(rt.representation<JointRequest>().position[kHeadYaw], stand_head);
  EXPECT_EQ(rt.representation<test::Counter>().n, 101);
  EXPECT_EQ(rt.representation<test::Doubled>().n, 202);
}

TEST(Override, BuiltInsAndErrors) {
  const auto registry = test::test_registry();
  FakeLink link;
  Runtime rt(registry, test::test_config(), link);
  rt.set("representation:SensorFrame", "angles=[0.5, 0]");
  for (int i = 0; i < 3; ++i) rt.step();
  EXPECT_EQ(rt.representation<InertialSensorData>().angles.x(), 0.5);  // the link said 0.02
  EXPECT_EQ(error_of([&] { rt.set("representation:JointRequest", "unchanged"); }),
            "representation 'JointRequest' is not overridden");
  EXPECT_EQ(error_of([&] { rt.set("representation:SensorFrame.angles", "unchanged"); }),
            "'unchanged' releases a whole representation: set representation:SensorFrame "
            "unchanged");
  // A bad text holds nothing.
  EXPECT_NE(error_of([&] { rt.set("representation:JointRequest", "position[Nose]=1"); }), "");
  EXPECT_EQ(rt.overrides().count("JointRequest"), 0u);
  EXPECT_EQ(rt.overrides().count("SensorFrame"), 1u);
}

struct Shouted {
  STRIDE_FIELDS(Shouted);
  STRIDE_FIELD(std::int64_t, n) = 0;
  static constexpr std::string_view kTypeName = "Shouted";
};

// Prints and plots the counter, and asks to stop at frame 5.
class Shouter final : public Module {
 public:
  explicit Shouter(ModuleContext& c)
      : counter_(c.require<test::Counter>()),
        out_(c.provide<Shouted>()),
        show_(c.debug_request("test:show")),
        stop_(c.debug_request("test:stop")) {}
  void update() override {
    out_.n = counter_.n;
    show_.show({{"n", static_cast<double>(counter_.n)}, {"half", 0.5 * counter_.n}});
    if (counter_.n == 5) stop_.stop("frame 5");
  }

 private:
  const test::Counter& counter_;
  Shouted& out_;
  DebugRequest show_, stop_;
};

TEST(DebugRequests, PrintPlotQuietAndStop) {
  auto registry = test::test_registry();
  registry.add<Shouter>("Shouter");
  FakeLink link;
  RuntimeConfig config = test::test_config();
  config.providers["Shouted"] = "Shouter";
  Runtime rt(registry, config, link);
  rt.step();
  EXPECT_EQ(rt.representation<Shouted>().n, 0);  // it ran, and said nothing while off
  // The runtime's own events are said whatever requests are on (here: the test config's zero
  // joint request clamped onto the limits); no request line is among them.
  for (const std::string& line : rt.take_debug_lines()) EXPECT_TRUE(line.starts_with("event: "));
  EXPECT_TRUE(rt.debug_values().empty());
  rt.set_debug_request("test:show", DebugSwitch::On);
  rt.set_debug_request("test:stop", DebugSwitch::Quiet);
  for (int i = 0; i < 3; ++i) rt.step();
  EXPECT_EQ(rt.take_debug_lines(),
            (std::vector<std::string>{"test:show: n=1 half=0.5", "test:show: n=2 half=1",
                                      "test:show: n=3 half=1.5"}));
  EXPECT_EQ(rt.debug_values().at("test:show.half"), 1.5);
  rt.set_debug_request("test:show", DebugSwitch::Quiet);
  for (int i = 0; i < 3; ++i) rt.step();
  EXPECT_TRUE(rt.take_debug_lines().empty());  // quiet: values only
  EXPECT_EQ(rt.debug_values().at("test:show.n"), 6);
  EXPECT_EQ(rt.take_debug_stop(), "test:stop: frame 5");
  EXPECT_EQ(rt.take_debug_stop(), "");  // taken
}

TEST(ModuleParameters, EveryModuleListsItsFieldsWithRanges) {
  const auto registry = test::test_registry();
  const auto lines = parameter_lines(registry);
  const auto has = [&](const std::string& line) {
    return std::find(lines.begin(), lines.end(), line) != lines.end();
  };
  EXPECT_TRUE(has("SensorConversion.fall_tilt = 0.8 [rad] in [0.05, 3.2]"));
  EXPECT_TRUE(has("SensorConversion.contact_force = 2 [N] in [0, 200]"));
  EXPECT_EQ(default_parameters(registry).count("Doubler"), 0u);  // no parameters
}

}  // namespace
}  // namespace stride
