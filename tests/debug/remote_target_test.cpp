// The console's RemoteTarget against a robot loop running in real time: debug requests in their
// three states, the debug output they print, plot and stop with, held `set` overrides and the
// provider:, override: and debug: keys answer over `connect` in the words the local console uses.
#include <gtest/gtest.h>

#include <cstdio>

#include "console/target/remote_target.hpp"
#include "robot/runtime/controller_keys.hpp"
#include "tests/debug/robot_loop.hpp"
#include "tests/error_text.hpp"

namespace stride::test {
namespace {

using test_support::error_of;

struct Traced {
  STRIDE_FIELDS(Traced);
  STRIDE_FIELD(std::int64_t, n) = 0;
  static constexpr std::string_view kTypeName = "Traced";
};

// Prints and plots the counter every frame ("test:trace") and asks to pause on every 25th
// frame ("test:pause").
class Tracer final : public Module {
 public:
  explicit Tracer(ModuleContext& c)
      : counter_(c.require<Counter>()),
        out_(c.provide<Traced>()),
        trace_(c.debug_request("test:trace")),
        pause_(c.debug_request("test:pause")) {}
  void update() override {
    out_.n = counter_.n;
    trace_.show({{"n", static_cast<double>(counter_.n)}, {"third", counter_.n / 3.0}});
    if (counter_.n % 25 == 0) pause_.stop("frame " + std::to_string(counter_.n));
  }

 private:
  const Counter& counter_;
  Traced& out_;
  DebugRequest trace_, pause_;
};

ModuleRegistry tracer_registry() {
  ModuleRegistry r = test_registry();
  r.add<Tracer>("Tracer");
  return r;
}

RuntimeConfig tracer_config() {
  RuntimeConfig c = test_config();
  c.providers["Traced"] = "Tracer";
  return c;
}

// Runs `frames` frames of the remote robot, keeping its debug output.
struct Advanced {
  std::vector<std::string> lines;
  std::string stop;
  std::uint64_t frames = 0;
};
Advanced advance(console::RemoteTarget& robot, std::uint64_t frames) {
  Advanced a;
  a.frames = robot.advance(frames, [&] {
    console::DebugOutput d = robot.take_debug_output();
    a.lines.insert(a.lines.end(), d.lines.begin(), d.lines.end());
    if (d.stop.empty()) return true;
    a.stop = d.stop;
    return false;
  });
  return a;
}

TEST(RemoteTarget, DebugRequestsInThreeStatesStreamTheirOutput) {
  RobotLoop loop(loopback_options(), 0.004, tracer_registry(), tracer_config());
  console::RemoteTarget robot(loop.endpoint(), "");

  using Listed = std::vector<std::pair<std::string, DebugSwitch>>;
  EXPECT_EQ(robot.debug_requests(), (Listed{{"test:negate", DebugSwitch::Off},
                                            {"robot:stop_on_fall", DebugSwitch::Off},
                                            {"test:trace", DebugSwitch::Off},
                                            {"test:pause", DebugSwitch::Off}}));
  // Off: nothing printed, and the value says how to switch it on, as locally.
  EXPECT_EQ(error_of([&] { robot.get("debug:test:trace.n"); }),
            "debug:test:trace.n: switch it on first (dr test:trace on)");
  EXPECT_TRUE(advance(robot, 10).lines.empty());

  robot.set_debug_request("test:trace", DebugSwitch::On);
  robot.observe({"debug:test:trace.n", "debug:test:trace.third", "representation:Traced.n"});
  // Every frame's line comes with that frame, with the counter it printed (%.5g, as show()
  // prints), and the streamed values are that frame's in all their digits.
  std::uint64_t frames = 0, matched = 0;
  robot.advance(10, [&] {
    ++frames;
    const console::DebugOutput d = robot.take_debug_output();
    const std::string n = robot.get("representation:Traced.n");
    char third[32];
    std::snprintf(third, sizeof third, "%.5g", std::stoll(n) / 3.0);
    matched += !d.lines.empty() && d.lines.back() == "test:trace: n=" + n + " third=" + third &&
               robot.get("debug:test:trace.n") == n &&
               robot.get("debug:test:trace.third") == debug_value_text(std::stoll(n) / 3.0);
    return true;
  });
  EXPECT_EQ(frames, 10u);
  EXPECT_EQ(matched, 10u);

  // Quiet: values still come, lines do not.
  robot.set_debug_request("test:trace", DebugSwitch::Quiet);
  EXPECT_EQ(robot.debug_requests()[2].second, DebugSwitch::Quiet);
  std::uint64_t quiet_lines = 0, same = 0;
  robot.advance(10, [&] {
    quiet_lines += robot.take_debug_output().lines.size();
    same += robot.get("debug:test:trace.n") == robot.get("representation:Traced.n");
    return true;
  });
  EXPECT_LE(quiet_lines, 1u);  // at most one frame's from before the switch
  EXPECT_EQ(same, 10u);
  // Asked outside a run, the robot answers from its latest frame, in the same words.
  EXPECT_NE(robot.get("debug:test:trace.n"), "");
  EXPECT_EQ(error_of([&] { robot.get("debug:test:trace.nope"); }),
            "debug:test:trace.nope: no such value (test:trace.n, test:trace.third)");

  // A request to pause ends the console's run at that frame; the robot keeps going.
  robot.set_debug_request("test:pause", DebugSwitch::On);
  Advanced paused = advance(robot, 200);
  EXPECT_LT(paused.frames, 200u);
  ASSERT_TRUE(paused.stop.starts_with("test:pause: frame ")) << paused.stop;
  const std::int64_t at = std::stoll(paused.stop.substr(18));
  EXPECT_EQ(at % 25, 0);
  robot.set_debug_request("test:pause", DebugSwitch::Off);
  robot.set_debug_request("test:trace", DebugSwitch::Off);
  EXPECT_EQ(error_of([&] { robot.set_debug_request("test:nope", DebugSwitch::On); }),
            "no debug request 'test:nope' (dr ? lists them)");
}

TEST(RemoteTarget, HeldOverridesAndProviderKeys) {
  RobotLoop loop(loopback_options(), 0.004, tracer_registry(), tracer_config());
  console::RemoteTarget robot(loop.endpoint(), "");
  EXPECT_EQ(robot.get("provider:Counter"), "CounterFromFrame");
  EXPECT_EQ(robot.get("provider:FrameInfo"), "(built-in)");
  EXPECT_EQ(robot.get("override:Counter"), "(none)");

  robot.set("representation:Counter", "n=7");
  EXPECT_EQ(robot.get("override:Counter"), "n=7");
  robot.observe({"representation:Counter.n", "representation:Traced.n"});
  std::uint64_t held = 0;
  robot.advance(20, [&] {
    held +=
        robot.get("representation:Counter.n") == "7" && robot.get("representation:Traced.n") == "7";
    return true;
  });
  EXPECT_EQ(held, 20u);  // every frame, against its provider, and its consumer saw it
  robot.set("representation:Counter", "unchanged");
  EXPECT_EQ(robot.get("override:Counter"), "(none)");
  std::string n;
  robot.advance(2, [&] {
    n = robot.get("representation:Counter.n");
    return true;
  });
  EXPECT_NE(n, "7");
  EXPECT_EQ(error_of([&] { robot.set("representation:Counter", "unchanged"); }),
            "representation 'Counter' is not overridden");
  EXPECT_EQ(error_of([&] { robot.get("override:Nope"); }),
            "no representation 'Nope' on the blackboard");
}

}  // namespace
}  // namespace stride::test
