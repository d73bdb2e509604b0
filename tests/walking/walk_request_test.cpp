// RequestWalk and ScriptedWalkRequest in a Runtime, and mid-walk parameter changes: PatternWalk
// refuses them with one line and keeps its walk (it used to rebuild the pattern mid-walk and fall),
// RequestWalk grants requests within its limits, says so in WalkStatus, and takes new pattern
// parameters when it stands again.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "behaviours/module_catalogue.hpp"
#include "behaviours/walking/modules/pattern_walk.hpp"
#include "behaviours/walking/modules/walk_request.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {
namespace {

class StillLink final : public hal::HardwareLink {
 public:
  bool read(hal::SensorFrame& s) override {
    s.time = n_++ * 0.01;
    return true;
  }
  void write(const hal::ActuatorFrame&) override {}
  double period() const override { return 0.01; }
  std::string name() const override { return "still"; }

 private:
  int n_ = 0;
};

const ModuleRegistry& registry() {
  static const ModuleRegistry r = [] {
    ModuleRegistry m;
    behaviours::register_all_modules(m);
    return m;
  }();
  return r;
}

RuntimeConfig config(const std::string& walker) {
  RuntimeConfig c;
  c.providers = {{"WalkingJointRequest", walker},
                 {"PostureCorrectedRequest", "NoPostureControl"},
                 {"ArmSwingRequest", "ArmSwing"},
                 {"JointRequest", "WalkingJointRequestAssembler"}};
  c.parameters["PatternWalk.start_delay"] = "0.6";
  return c;
}

void steps(Runtime& rt, double seconds) {
  for (int i = 0; i < static_cast<int>(std::lround(seconds / 0.01)); ++i) ASSERT_TRUE(rt.step());
}

// The walking modules' lines among the runtime's (the still link also draws safety events).
std::vector<std::string> walking_lines(Runtime& rt) {
  std::vector<std::string> out;
  for (std::string& line : rt.take_debug_lines())
    if (line.rfind("walking:", 0) == 0) out.push_back(std::move(line));
  return out;
}

bool all_finite(const WalkingJointRequest& r) {
  for (double q : r.position)
    if (!std::isfinite(q)) return false;
  return true;
}

TEST(WalkRequest, PatternWalkRefusesAPresetChangeMidWalkWithOneLineAndKeepsWalking) {
  StillLink link;
  Runtime rt(registry(), config("PatternWalk"), link);
  steps(rt, 2.0);  // walking since 0.6 s
  rt.take_debug_lines();
  rt.set_parameters("PatternWalk", "preset=fast");
  const walking::StretchedKneePattern medium(walking::preset("medium"));
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(rt.step());
    const auto& r = rt.representation<WalkingJointRequest>();
    ASSERT_TRUE(all_finite(r));
    const double t = rt.representation<FrameInfo>().time - 0.6;
    const WalkingJointRequest want =
        behaviours::walking_request(walking::leg_joints(medium.sample(t)));
    ASSERT_EQ(r.position, want.position) << "t=" << t;  // the medium walk goes on, bit for bit
  }
  const auto lines = walking_lines(rt);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0],
            "walking:parameters: refused: PatternWalk plays the walk it started with to its end; "
            "its parameters change before the walk starts or after reset (RequestWalk changes "
            "speed while walking)");
  EXPECT_EQ(rt.get("module:PatternWalk.preset"), "fast");  // held, and said to be refused
}

TEST(WalkRequest, PatternWalkTakesAPresetChangeBeforeItsWalkStarts) {
  StillLink link;
  Runtime rt(registry(), config("PatternWalk"), link);
  steps(rt, 0.3);
  rt.set_parameters("PatternWalk", "preset=fast");
  steps(rt, 0.5);  // t = 0.2 s into the fast walk
  const double t = rt.representation<FrameInfo>().time - 0.6;
  const walking::StretchedKneePattern fast(walking::preset("fast"));
  EXPECT_EQ(rt.representation<WalkingJointRequest>().position,
            behaviours::walking_request(walking::leg_joints(fast.sample(t))).position);
  for (const std::string& line : walking_lines(rt)) ADD_FAILURE() << line;
}

TEST(WalkRequest, RequestWalkGrantsWithinItsLimitsAndSaysSo) {
  StillLink link;
  Runtime rt(registry(), config("RequestWalk"), link);
  steps(rt, 0.5);
  EXPECT_EQ(rt.get("representation:WalkStatus.state"), "standing");
  rt.set_parameters("ScriptedWalkRequest", "mode=walk forward=0.5 turn=-2");
  steps(rt, 1.0);  // stands up until 1 s, then walks
  const auto& status = rt.representation<WalkStatus>();
  EXPECT_EQ(status.state, WalkState::walking);
  EXPECT_TRUE(status.limited);
  EXPECT_TRUE(status.ramping);
  steps(rt, 2.0);
  EXPECT_DOUBLE_EQ(status.granted_forward, 0.22);  // max_forward
  EXPECT_DOUBLE_EQ(status.granted_turn, -0.6);     // max_turn
  EXPECT_TRUE(status.limited);
  EXPECT_FALSE(status.ramping);
  EXPECT_LT(status.odometry[2], -0.3);
  // The console's held value steers it as the module's parameters do.
  rt.set("representation:WalkRequest", "forward=0.1 turn=0");
  steps(rt, 2.0);
  EXPECT_DOUBLE_EQ(status.granted_forward, 0.1);
  EXPECT_DOUBLE_EQ(status.granted_turn, 0.0);
  EXPECT_FALSE(status.limited);
  EXPECT_EQ(rt.get("representation:WalkStatus.granted_forward"), "0.1");
  EXPECT_EQ(status.ik_beyond_limit_frames, 0);
  EXPECT_TRUE(all_finite(rt.representation<WalkingJointRequest>()));
}

TEST(WalkRequest, RequestWalkTakesNewPatternParametersWhenItStandsAgain) {
  StillLink link;
  Runtime rt(registry(), config("RequestWalk"), link);
  const int knee = hal::index(hal::JointId::LKneePitch);
  steps(rt, 1.2);  // stood up on the medium preset
  const double knee_medium = rt.representation<WalkingJointRequest>().position[knee];
  rt.set_parameters("ScriptedWalkRequest", "mode=walk forward=0.15");
  steps(rt, 2.0);
  const auto& status = rt.representation<WalkStatus>();
  rt.set_parameters("RequestWalk", "preset=fast");
  steps(rt, 1.0);
  EXPECT_TRUE(status.parameters_pending);
  EXPECT_EQ(status.state, WalkState::walking);
  EXPECT_TRUE(all_finite(rt.representation<WalkingJointRequest>()));
  rt.set_parameters("ScriptedWalkRequest", "mode=stand");
  int walking_frames = 0, stopping_frames = 0;
  for (int i = 0; i < 200 && status.state != WalkState::standing; ++i) {
    ASSERT_TRUE(rt.step());
    walking_frames += status.state == WalkState::walking;
    stopping_frames += status.state == WalkState::stopping;
  }
  // 0.15 m/s slows by two steps of 0.06 m/s, then the last step plans the stop.
  EXPECT_GT(walking_frames, 30);
  EXPECT_LT(walking_frames, 80);
  EXPECT_GT(stopping_frames, 20);
  EXPECT_EQ(status.state, WalkState::standing);
  EXPECT_FALSE(status.parameters_pending);
  // Standing on the fast preset's lower waist (0.315 m against 0.325 m): more bent knees.
  const double knee_fast = rt.representation<WalkingJointRequest>().position[knee];
  EXPECT_GT(knee_fast, knee_medium + 0.05);
  rt.set_parameters("RequestWalk", "z_max=0.5");  // beyond the leg: kept out, said once
  steps(rt, 0.2);
  const auto lines = walking_lines(rt);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("walking:request: RequestWalk keeps its pattern: WalkParameters: z_max"),
            std::string::npos)
      << lines[0];
  EXPECT_TRUE(all_finite(rt.representation<WalkingJointRequest>()));
}

// The still link's gyro says the torso never turns: the heading loop turns the plan further than
// the granted requests, by at most max_turn more; without it the plan is the requests' path.
TEST(WalkRequest, HeadingLoopTurnsThePlanWhileTheGyroLags) {
  for (const double gain : {0.0, 1.0}) {
    StillLink link;
    Runtime rt(registry(), config("RequestWalk"), link);
    rt.set_parameters("RequestWalk", "heading_gain=" + std::to_string(gain));
    rt.set_parameters("ScriptedWalkRequest", "mode=walk turn=0.3");
    steps(rt, 5.0);
    const auto& status = rt.representation<WalkStatus>();
    EXPECT_EQ(status.measured_yaw, 0.0);
    EXPECT_GT(status.odometry[2], 1.0);  // about 0.3 rad/s for 4 s
    if (gain == 0.0) {
      EXPECT_EQ(status.plan, status.odometry);
    } else {
      // The plan turns at up to max_turn (0.6) more: ahead of the requests' path, by at most that.
      EXPECT_GT(status.plan[2] - status.odometry[2], 0.5);
      EXPECT_LT(status.plan[2] - status.odometry[2], 0.6 * 4.0);
      EXPECT_DOUBLE_EQ(status.granted_turn, 0.3);  // what is granted stays the request
    }
    EXPECT_EQ(status.ik_beyond_limit_frames, 0) << gain;
  }
}

// Walking to a pose of the odometry's frame: the walk goes there, slowing as it comes near, and
// stands within 2 cm and 0.05 rad of it (plus what the last steps carry on).
TEST(WalkRequest, TargetModeWalksToThePoseAndStands) {
  StillLink link;
  Runtime rt(registry(), config("RequestWalk"), link);
  rt.set_parameters("ScriptedWalkRequest", "mode=target target=[0.4, 0.1, 0.6]");
  const auto& status = rt.representation<WalkStatus>();
  bool walked = false;
  for (int i = 0; i < 2000 && !(walked && status.state == WalkState::standing); ++i) {
    ASSERT_TRUE(rt.step());
    walked = walked || status.state == WalkState::walking;
  }
  EXPECT_TRUE(walked);
  EXPECT_EQ(status.state, WalkState::standing);
  EXPECT_NEAR(status.odometry[0], 0.4, 0.03);
  EXPECT_NEAR(status.odometry[1], 0.1, 0.03);
  EXPECT_NEAR(status.odometry[2], 0.6, 0.06);
  EXPECT_LT(rt.representation<FrameInfo>().time, 15.0);
  EXPECT_EQ(status.ik_beyond_limit_frames, 0);
  // Standing there, it stays: no step is planned while it has arrived.
  const std::int64_t steps_then = status.steps;
  steps(rt, 2.0);
  EXPECT_EQ(status.steps, steps_then);
}

}  // namespace
}  // namespace stride
