// The frame loop: sensors -> modules -> actuators, parameters, provider swaps, debug requests.
#include <gtest/gtest.h>

#include "robot/nao/joint_limits.hpp"

#include "robot/runtime/runtime.hpp"
#include "tests/error_text.hpp"
#include "tests/framework/fake_link.hpp"

namespace stride {
namespace {

using test::FakeLink;

using stride::test_support::error_of;

TEST(Runtime, OneStepRunsSensorsModulesAndActuators) {
  const auto registry = test::test_registry();
  FakeLink link(0.012);
  Runtime rt(registry, test::test_config(), link);
  EXPECT_EQ(rt.module_order(),
            (std::vector<std::string>{"CounterFromFrame", "Doubler", "SensorConversion", "Stand",
                                      "ActuatorConversion"}));
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(rt.step());
  EXPECT_EQ(link.writes, 3);
  const auto& info = rt.representation<FrameInfo>();
  EXPECT_EQ(info.frame, 2);
  EXPECT_EQ(info.period, 0.012);  // read from the link
  EXPECT_EQ(info.time, 2 * 0.012);
  EXPECT_EQ(rt.representation<test::Doubled>().n, 4);
  const auto& fsr = rt.representation<FsrSensorData>();
  EXPECT_NEAR(fsr.total_left, 5 + 6 + 7 + 8 + 4 * 0.1 * std::cos(0.1), 1e-12);
  EXPECT_EQ(rt.representation<ModuleTimes>().modules, rt.module_order());
  // What reaches the servos is the request clamped to the joint limits (nao-facts.md).
  const auto& request = rt.representation<JointRequest>().position;
  int clamped = 0;
  for (int i = 0; i < hal::kNumJoints; ++i) {
    const auto& lim = nao::kJointLimits[i];
    EXPECT_EQ(link.last.position[i], std::clamp(request[i], lim.lower, lim.upper)) << i;
    clamped += link.last.position[i] != request[i];
  }
  EXPECT_GT(clamped, 0);  // the fake sensors put some joints (e.g. the elbow rolls) outside
}

TEST(Runtime, StandInterpolatesFromTheMeasuredPoseToThePosture) {
  const auto registry = test::test_registry();
  FakeLink link(0.01);
  RuntimeConfig config = test::test_config();
  config.parameters = {{"Stand.interpolation_time", "0.5"}, {"Stand.stiffness", "0.7"}};
  Runtime rt(registry, config, link);
  ASSERT_TRUE(rt.step());
  const auto measured = rt.representation<JointSensorData>().position;
  const auto target = behaviours::stand_posture(behaviours::StandParameters{});
  // Frame 0: 0.01 s of 0.5 s done; blend = (1 - cos(pi * 0.02)) / 2.
  const double blend = 0.5 - 0.5 * std::cos(std::numbers::pi * 0.02);
  const int knee = hal::index(hal::JointId::LKneePitch);
  EXPECT_NEAR(link.last.position[knee], measured[knee] + blend * (target[knee] - measured[knee]),
              1e-15);
  EXPECT_EQ(link.last.stiffness[knee], 0.7);
  for (int i = 0; i < 60; ++i) rt.step();
  for (int j = 0; j < hal::kNumJoints; ++j) EXPECT_NEAR(link.last.position[j], target[j], 1e-12);
  EXPECT_EQ(target[knee], nao::kStandKneePitch);
  EXPECT_EQ(target[hal::index(hal::JointId::RShoulderRoll)], -0.1);
  EXPECT_EQ(target[hal::index(hal::JointId::RElbowRoll)], 0.05);
}

TEST(Runtime, ParametersAreValidatedAndNeverHalfApplied) {
  const auto registry = test::test_registry();
  FakeLink link;
  Runtime rt(registry, test::test_config(), link);
  rt.set_parameters("Stand", "knee_pitch=0.5 hip_pitch=-0.2");
  EXPECT_EQ(rt.get("module:Stand.knee_pitch"), "0.5");
  EXPECT_EQ(error_of([&] { rt.set_parameters("Stand", "knee_pitch=0.4 hip_pitch=abc"); }),
            "Stand.hip_pitch: expected a number, got 'abc'");
  EXPECT_EQ(error_of([&] { rt.set_parameters("Stand", "hip_pitch=-0.1 knee_pitch=3"); }),
            "Stand.knee_pitch: 3 is outside [-0.0923279, 2.11255]");
  EXPECT_EQ(rt.get("module:Stand.knee_pitch"), "0.5");
  EXPECT_EQ(rt.get("module:Stand.hip_pitch"), "-0.2");
  EXPECT_EQ(error_of([&] { rt.set_parameters("Walk", "x=1"); }),
            "no module 'Walk' with parameters");
  RuntimeConfig bad = test::test_config();
  bad.parameters = {{"Stand.stiffness", "2"}};
  EXPECT_EQ(error_of([&] { Runtime r(registry, bad, link); }),
            "Stand.stiffness: 2 is outside [0, 1]");
  bad.parameters = {{"Stand", "2"}};
  EXPECT_EQ(error_of([&] { Runtime r(registry, bad, link); }),
            "parameter 'Stand': expected Module.field");
}

TEST(Runtime, GetAndSetByConsoleKey) {
  const auto registry = test::test_registry();
  FakeLink link;
  Runtime rt(registry, test::test_config(), link);
  for (int i = 0; i < 4; ++i) rt.step();
  EXPECT_EQ(rt.get("representation:FrameInfo.frame"), "3");
  EXPECT_EQ(rt.get("representation:FrameInfo"), "{time=0.03, frame=3, period=0.01}");
  rt.set("representation:JointRequest", "position[3]=0.5");
  EXPECT_EQ(rt.get("representation:JointRequest.position[3]"), "0.5");
  rt.set("module:Stand.stiffness", "0.25");
  EXPECT_EQ(rt.get("module:Stand.stiffness"), "0.25");
  EXPECT_EQ(type_label(rt.type_of("representation:FsrSensorData.cop_left")), "double[2]");
  EXPECT_EQ(error_of([&] { rt.get("representation:Ball"); }),
            "no representation 'Ball' on the blackboard");
  EXPECT_EQ(error_of([&] { rt.get("ball"); }),
            "key 'ball': expected representation:<Name> or module:<Name>");
}

TEST(Runtime, ProviderSwapMidRunChangesProducerAndOrder) {
  const auto registry = test::test_registry();
  FakeLink link;
  Runtime rt(registry, test::test_config(), link);
  EXPECT_EQ(rt.providers_available("Counter"),
            (std::vector<std::string>{"CounterAfterStand", "CounterFromFrame"}));
  rt.step();
  rt.step();
  EXPECT_EQ(rt.representation<test::Doubled>().n, 2);
  rt.swap_provider("Counter", "CounterAfterStand");
  EXPECT_EQ(rt.provider_of("Counter"), "CounterAfterStand");
  EXPECT_EQ(rt.module_order(),
            (std::vector<std::string>{"SensorConversion", "Stand", "ActuatorConversion",
                                      "CounterAfterStand", "Doubler"}));
  rt.step();  // frame 2
  EXPECT_EQ(rt.representation<test::Counter>().n, -1002);
  EXPECT_EQ(rt.representation<test::Doubled>().n, -2004);
  EXPECT_EQ(rt.representation<FrameInfo>().frame, 2);  // no restart
  rt.swap_provider("Counter", "default");
  EXPECT_EQ(rt.provider_of("Counter"), "CounterFromFrame");
  rt.step();
  EXPECT_EQ(rt.representation<test::Doubled>().n, 6);
  EXPECT_EQ(error_of([&] { rt.swap_provider("Counter", "Stand"); }),
            "mr: 'Stand' does not provide 'Counter' (its providers: CounterAfterStand, "
            "CounterFromFrame)");
  // An unknown representation is an error too, even with "default" (it used to pass silently).
  const std::string unknown = error_of([&] { rt.swap_provider("NoSuchRep", "default"); });
  EXPECT_NE(unknown.find("mr: no module provides a representation 'NoSuchRep' (representations "
                         "with providers: "),
            std::string::npos)
      << unknown;
  EXPECT_NE(unknown.find("Counter, "), std::string::npos) << unknown;
  EXPECT_EQ(rt.provider_of("Counter"), "CounterFromFrame");  // failed swaps change nothing
  EXPECT_EQ(rt.provider_of("NoSuchRep"), "");
}

TEST(Runtime, ConfigurationErrorsNameTheModules) {
  const auto registry = test::test_registry();
  FakeLink link;
  RuntimeConfig c;
  c.providers = {{"Doubled", "Doubler"}};
  EXPECT_EQ(error_of([&] { Runtime r(registry, c, link); }),
            "representation 'Counter' has several providers (CounterAfterStand, "
            "CounterFromFrame); choose one in the configuration");
  ModuleRegistry small;
  behaviours::register_stand(small);
  EXPECT_EQ(error_of([&] { Runtime r(small, {}, link); }),
            "no provider for representation 'ActuatorFrame' (required by the runtime)");
}

TEST(Runtime, DebugRequestsAreListedAndToggled) {
  const auto registry = test::test_registry();
  FakeLink link;
  Runtime rt(registry, test::test_config(), link);
  using Listed = std::vector<std::pair<std::string, DebugSwitch>>;
  // In the order the modules registered them (the registry's, by name).
  EXPECT_EQ(rt.debug_requests(),
            (Listed{{"test:negate", DebugSwitch::Off}, {"robot:stop_on_fall", DebugSwitch::Off}}));
  rt.step();
  rt.step();
  EXPECT_EQ(rt.representation<test::Doubled>().n, 2);
  rt.set_debug_request("test:negate", DebugSwitch::On);
  rt.step();
  EXPECT_EQ(rt.representation<test::Doubled>().n, -4);
  EXPECT_EQ(rt.debug_requests()[0].second, DebugSwitch::On);
  EXPECT_EQ(error_of([&] { rt.set_debug_request("nope", DebugSwitch::On); }),
            "no debug request 'nope' (dr ? lists them)");
}

TEST(Runtime, LostLinkRunsNothing) {
  const auto registry = test::test_registry();
  FakeLink link(0.01, 2);
  Runtime rt(registry, test::test_config(), link);
  EXPECT_TRUE(rt.step());
  EXPECT_TRUE(rt.step());
  EXPECT_FALSE(rt.step());
  EXPECT_EQ(link.writes, 2);
}

}  // namespace
}  // namespace stride
