// PatternWalk / ConventionalWalk in a Runtime: standing blend, the pattern's leg IK angles bit for
// bit at FrameInfo time, the final pose held, swapping, and parameter errors.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "behaviours/module_catalogue.hpp"
#include "behaviours/stand/stand.hpp"
#include "behaviours/walking/modules/pattern_walk.hpp"
#include "behaviours/walking/modules/walk_parameters.hpp"
#include "behaviours/walking/modules/walk_plan.hpp"
#include "robot/core/error.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {
namespace {

using behaviours::walking_request;
using walking::leg_joints;

// A robot frozen in a crouch, sampled at an unusual period so nothing may assume 10 ms.
class StillLink final : public hal::HardwareLink {
 public:
  static constexpr double kPeriod = 0.012;
  bool read(hal::SensorFrame& s) override {
    s.time = 5.0 + n_++ * kPeriod;  // the link clock does not start at zero
    for (int i = 0; i < hal::kNumJoints; ++i) s.position[i] = 0.01 * i;
    return true;
  }
  void write(const hal::ActuatorFrame&) override {}
  double period() const override { return kPeriod; }
  std::string name() const override { return "still"; }

 private:
  int n_ = 0;
};

RuntimeConfig walk_config(const std::string& walker, const std::string& preset) {
  RuntimeConfig c;
  c.providers = {{"WalkingJointRequest", walker},
                 {"PostureCorrectedRequest", "NoPostureControl"},
                 {"ArmSwingRequest", "ArmSwing"},
                 {"JointRequest", "WalkingJointRequestAssembler"}};
  for (const std::string m : {"PatternWalk", "ConventionalWalk"}) {
    c.parameters[m + ".preset"] = preset;
    c.parameters[m + ".start_delay"] = "0.6";
    c.parameters[m + ".interpolation_time"] = "0.3";
  }
  return c;
}

struct Rig {
  explicit Rig(const std::string& walker, const std::string& preset = "medium")
      : rt(registry(), walk_config(walker, preset), link) {}
  static const ModuleRegistry& registry() {
    static const ModuleRegistry r = [] {
      ModuleRegistry m;
      behaviours::register_all_modules(m);
      return m;
    }();
    return r;
  }
  const WalkingJointRequest& request() const { return rt.representation<WalkingJointRequest>(); }
  double time() const { return rt.representation<FrameInfo>().time; }
  StillLink link;
  Runtime rt;
};

void expect_bitwise(const WalkingJointRequest& got, const WalkingJointRequest& want,
                    const std::string& when) {
  for (int i = 0; i < hal::kNumJoints; ++i) {
    EXPECT_EQ(got.position[i], want.position[i]) << hal::kJointNames[i] << " " << when;
    EXPECT_EQ(got.stiffness[i], want.stiffness[i]) << hal::kJointNames[i] << " " << when;
  }
}

template <class Pattern>
void expect_plays_pattern(const std::string& walker, const std::string& preset) {
  Rig rig(walker, preset);
  const Pattern pattern(walking::preset(preset));
  const double start_delay = 0.6;
  ASSERT_TRUE(rig.rt.step());
  const double first = rig.time();
  for (int i = 0; i < hal::kNumJoints; ++i)  // the blend starts at the measured pose
    EXPECT_DOUBLE_EQ(rig.request().position[i], 0.01 * i) << hal::kJointNames[i];
  int compared = 0;
  while (rig.time() - first < start_delay + pattern.duration() + 0.5) {
    ASSERT_TRUE(rig.rt.step());
    const double elapsed = rig.time() - first;
    const double t = elapsed - start_delay;  // FrameInfo time since the walk started
    if (elapsed >= 0.3 && t < 0) {
      expect_bitwise(rig.request(), walking_request(leg_joints(pattern.sample(0.0))), "standing");
    } else if (t >= 0 && t <= pattern.duration() && compared++ % 37 == 0) {
      expect_bitwise(rig.request(), walking_request(leg_joints(pattern.sample(t))),
                     "t=" + std::to_string(t));
      const WalkPlan& plan = rig.rt.representation<WalkPlan>();  // from the very sample played
      EXPECT_EQ(plan.zmp[0], pattern.sample(t).zmp.x()) << "t=" << t;
      EXPECT_EQ(plan.zmp[1], pattern.sample(t).zmp.y()) << "t=" << t;
      EXPECT_EQ(plan.steps, walking::walk_plan(pattern.sample(t), pattern.footsteps(), t).steps);
    } else if (t > pattern.duration()) {
      expect_bitwise(rig.request(), walking_request(leg_joints(pattern.sample(pattern.duration()))),
                     "after the walk");
    }
  }
  EXPECT_GT(compared, 1000);  // 15 s at 12 ms
}

TEST(WalkModules, PatternWalkPlaysTheStretchedKneePatternAtFrameTime) {
  expect_plays_pattern<walking::StretchedKneePattern>("PatternWalk", "medium");
}

TEST(WalkModules, ConventionalWalkPlaysTheConstantHeightPattern) {
  expect_plays_pattern<walking::ConventionalPattern>("ConventionalWalk", "fast");
}

TEST(WalkModules, LegsAtFullStiffnessArmsFromStand) {
  const WalkingJointRequest r = walking_request(
      leg_joints(walking::StretchedKneePattern(walking::preset("slow")).sample(3.0)));
  const auto stand = behaviours::stand_posture(behaviours::StandParameters{});
  for (auto j : {hal::JointId::LKneePitch, hal::JointId::RAnkleRoll, hal::JointId::LHipYawPitch})
    EXPECT_EQ(r.stiffness[hal::index(j)], 1.0) << hal::name(j);
  for (auto j : {hal::JointId::LShoulderPitch, hal::JointId::RElbowRoll, hal::JointId::HeadYaw}) {
    EXPECT_EQ(r.position[hal::index(j)], stand[hal::index(j)]) << hal::name(j);
    EXPECT_EQ(r.stiffness[hal::index(j)], behaviours::StandParameters{}.stiffness);
  }
}

TEST(WalkModules, SwappingToConventionalWalkStandsUpIntoItsBentKneePose) {
  Rig rig("PatternWalk");
  for (int i = 0; i < 300; ++i) ASSERT_TRUE(rig.rt.step());  // 3.6 s: walking
  rig.rt.swap_provider("WalkingJointRequest", "ConventionalWalk");
  ASSERT_TRUE(rig.rt.step());
  EXPECT_EQ(rig.rt.provider_of("WalkingJointRequest"), "ConventionalWalk");
  const double first = rig.time();
  for (int i = 0; i < hal::kNumJoints; ++i)  // the newcomer starts from the measured pose
    EXPECT_DOUBLE_EQ(rig.request().position[i], 0.01 * i) << hal::kJointNames[i];
  while (rig.time() - first < 0.4) ASSERT_TRUE(rig.rt.step());  // blended, not yet walking
  const WalkingJointRequest bent = walking_request(
      leg_joints(walking::ConventionalPattern(walking::preset("medium")).sample(0)));
  expect_bitwise(rig.request(), bent, "conventional first pose");
  const WalkingJointRequest stretched = walking_request(
      leg_joints(walking::StretchedKneePattern(walking::preset("medium")).sample(0)));
  const int knee = hal::index(hal::JointId::LKneePitch);
  EXPECT_GT(bent.position[knee], stretched.position[knee]);  // 0.318 m < z_min = 0.323 m
}

TEST(WalkModules, OverridesReplaceThePresetValues) {
  behaviours::WalkParameters w;
  w.preset = behaviours::WalkPreset::slow;
  w.H_foot = 0.02;
  w.steps = 20;
  w.V_max = 0.1;
  const walking::PatternParameters p = behaviours::walk_pattern_parameters(w);
  const walking::PatternParameters slow = walking::preset("slow");
  EXPECT_EQ(p.H_foot, 0.02);
  EXPECT_EQ(p.steps, 20);
  EXPECT_EQ(p.rhythmic.V_max, 0.1);
  EXPECT_EQ(p.rhythmic.V_min, slow.rhythmic.V_min);
  EXPECT_EQ(p.z_max, slow.z_max);
  EXPECT_EQ(p.development_steps(), slow.development_steps());
  EXPECT_DOUBLE_EQ(p.development.back().V_max, 0.1 * 2.0 / 3.0);  // the ramp leads to the new speed
}

TEST(WalkModules, BadParametersNameTheField) {
  behaviours::WalkParameters w;
  w.z_max = 0.5;
  try {
    behaviours::walk_pattern_parameters(w);
    FAIL() << "z_max = 0.5 m accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("z_max"), std::string::npos) << e.what();
  }
  Rig rig("PatternWalk");
  rig.rt.set_parameters("PatternWalk", "T_stride=-1");
  try {
    rig.rt.step();
    FAIL() << "T_stride = -1 accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("T_stride"), std::string::npos) << e.what();
  }
  EXPECT_THROW(rig.rt.set_parameters("PatternWalk", "preset=brisk"), Error);
}

}  // namespace
}  // namespace stride

namespace stride {
namespace {

// A waist 0.2 m above the soles needs knees of about 2.4 rad, beyond the NAO's 2.11: the walk
// counts every such frame and says which joints.
TEST(WalkModules, CountsFramesWhoseLegIkIsBeyondTheJointLimits) {
  RuntimeConfig crouched = walk_config("PatternWalk", "medium");
  crouched.parameters["PatternWalk.z_min"] = "0.2";
  crouched.parameters["PatternWalk.z_max"] = "0.2";
  StillLink link;
  Runtime rt(Rig::registry(), crouched, link);
  for (int i = 0; i < 100; ++i) rt.step();
  const auto& r = rt.representation<WalkingJointRequest>();
  EXPECT_EQ(r.ik_beyond_limit_frames, 100);
  EXPECT_TRUE(r.ik_beyond_limits & (1u << 3)) << "left knee";
  EXPECT_TRUE(r.ik_beyond_limits & (1u << 9)) << "right knee";

  Rig medium("PatternWalk");  // the thesis' medium walk stays within the limits throughout
  for (int i = 0; i < 1500; ++i) medium.rt.step();
  EXPECT_EQ(medium.request().ik_beyond_limit_frames, 0);
}

}  // namespace
}  // namespace stride
