// The last line before the motors: limits, stiffness range, NaN holds the joint's last valid
// command (never 0 rad), and a module's exception under ModuleErrorPolicy::Hold.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "robot/runtime/command_guard.hpp"
#include "robot/runtime/runtime.hpp"
#include "tests/framework/fake_link.hpp"

namespace stride {
namespace {

const int kKnee = hal::index(hal::JointId::LKneePitch);
const int kHead = hal::index(hal::JointId::HeadYaw);

hal::SensorFrame standing() {
  hal::SensorFrame s;
  s.position.fill(0.1);
  s.position[kKnee] = 0.9;
  s.stiffness.fill(0.8);
  return s;
}

TEST(CommandGuard, ClampsToTheLimitsAndCountsEachJoint) {
  CommandGuard guard(lola_joint_limits(nullptr));
  guard.hold_measured(standing());
  CommandSafety counts;
  hal::ActuatorFrame a;
  const auto limits = lola_joint_limits(nullptr);
  for (int i = 0; i < hal::kNumJoints; ++i)  // every joint inside its range but two
    a.position[i] = 0.5 * (limits[i].lower + limits[i].upper);
  a.stiffness.fill(0.5);
  a.position[kKnee] = 2.6;  // the limit is 2.11255
  a.stiffness[kHead] = 1.5;
  guard.apply(a, counts);
  EXPECT_EQ(a.position[kKnee], 2.11255);
  EXPECT_EQ(a.stiffness[kHead], 1.0);
  EXPECT_EQ(counts.clamped_positions, 1);
  EXPECT_EQ(counts.clamped_stiffness, 1);
  EXPECT_EQ(counts.nonfinite_held, 0);
}

TEST(CommandGuard, NanHoldsTheLastValidCommandNeverZero) {
  CommandGuard guard(lola_joint_limits(nullptr));
  guard.hold_measured(standing());
  CommandSafety counts;
  hal::ActuatorFrame first;
  first.position = standing().position;
  first.stiffness.fill(1.0);
  first.position[kKnee] = 1.2;
  guard.apply(first, counts);
  hal::ActuatorFrame bad = first;
  bad.position[kKnee] = std::nan("");
  bad.stiffness[kHead] = INFINITY;
  guard.apply(bad, counts);
  EXPECT_EQ(bad.position[kKnee], 1.2);  // the last valid one, not 0 rad
  EXPECT_EQ(bad.stiffness[kHead], 1.0);
  EXPECT_EQ(counts.nonfinite_held, 2);
  // Before any command: the measured position at the measured stiffness.
  CommandGuard fresh(lola_joint_limits(nullptr));
  fresh.hold_measured(standing());
  hal::ActuatorFrame nan_first;
  nan_first.position.fill(std::nan(""));
  nan_first.stiffness.fill(std::nan(""));
  fresh.apply(nan_first, counts);
  EXPECT_EQ(nan_first.position[kKnee], 0.9);
  EXPECT_EQ(nan_first.stiffness[kKnee], 0.8);
}

// Provides JointRequest like Stand, but throws from frame `fail_from` on (a parameter).
struct ThrowParams {
  STRIDE_FIELDS(ThrowParams);
  STRIDE_FIELD(std::int64_t, fail_from) = 3;
  static constexpr std::string_view kTypeName = "ThrowParams";
};

class ThrowingStand final : public Module {
 public:
  explicit ThrowingStand(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        params_(c.parameters<ThrowParams>()),
        out_(c.provide<JointRequest>()) {}
  void update() override {
    if (frame_.frame >= params_.fail_from) throw std::runtime_error("walk table out of range");
    out_.position.fill(0.05 * static_cast<double>(frame_.frame + 1));
    out_.stiffness.fill(1.0);
  }

 private:
  const FrameInfo& frame_;
  const ThrowParams& params_;
  JointRequest& out_;
};

ModuleRegistry throwing_registry() {
  ModuleRegistry r = test::test_registry();
  r.add<ThrowingStand>("ThrowingStand");
  return r;
}

TEST(RuntimeModuleError, HoldPolicySendsTheLastSafeCommandAndRecordsOnce) {
  const auto registry = throwing_registry();
  test::FakeLink link(0.012);
  RuntimeConfig config = test::test_config();
  config.providers["JointRequest"] = "ThrowingStand";
  config.on_module_error = ModuleErrorPolicy::Hold;
  Runtime rt(registry, config, link);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(rt.step());
  const hal::ActuatorFrame safe = link.last;
  EXPECT_EQ(safe.position[kHead], 0.05 * 3);           // frame 2's, the last before the throw
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(rt.step());  // the loop goes on
  EXPECT_EQ(link.writes, 8);                           // every frame answered
  EXPECT_EQ(link.last.position, safe.position);        // with the last safe command
  ASSERT_EQ(rt.module_faults().size(), 1u);            // reported once, by name
  EXPECT_EQ(rt.module_faults()[0].module, "ThrowingStand");
  EXPECT_EQ(rt.module_faults()[0].message, "walk table out of range");
  EXPECT_EQ(rt.module_faults()[0].frame, 3);
  EXPECT_EQ(rt.module_faults()[0].count, 5);
  const auto& s = rt.representation<CommandSafety>();
  EXPECT_EQ(s.held_frames, 5);
  EXPECT_EQ(s.module_errors, 5);
  EXPECT_EQ(s.first_error, "ThrowingStand: walk table out of range");
  // Fixed between frames (here: a parameter), the module runs again.
  rt.set_parameters("ThrowingStand", "fail_from=1000");
  ASSERT_TRUE(rt.step());
  EXPECT_EQ(link.last.position[kHead], 0.05 * 9);
}

TEST(RuntimeModuleError, PropagatePolicyLeavesStep) {
  const auto registry = throwing_registry();
  test::FakeLink link(0.012);
  RuntimeConfig config = test::test_config();
  config.providers["JointRequest"] = "ThrowingStand";
  config.parameters["ThrowingStand.fail_from"] = "0";
  Runtime rt(registry, config, link);
  EXPECT_THROW(rt.step(), std::runtime_error);
}

TEST(RuntimeRobotModel, ModuleNeedingTheModelFailsByNameWithoutOne) {
  ModuleRegistry r = test::test_registry();
  struct NeedsModel final : Module {
    explicit NeedsModel(ModuleContext& c) : links(c.robot_model().links.size()) {
      c.provide<test::Doubled>();
    }
    void update() override {}
    std::size_t links;
  };
  r.add<NeedsModel>("NeedsModel");
  test::FakeLink link;
  RuntimeConfig config = test::test_config();
  config.providers["Doubled"] = "NeedsModel";
  try {
    Runtime rt(r, config, link);
    ADD_FAILURE() << "built without a model";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "module 'NeedsModel' needs the robot's model (its URDF), and this runtime was given "
              "none");
  }
  config.model = std::make_shared<const model::RobotModel>();
  EXPECT_NO_THROW(Runtime(r, config, link));
}

}  // namespace
}  // namespace stride
