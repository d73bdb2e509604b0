// The Ch. 4 modules in a Runtime: planning, the estimator on a leaning torso, provider swaps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "behaviours/posture/posture_modules.hpp"
#include "behaviours/posture/posture_representations.hpp"
#include "behaviours/posture/walking_joint_request.hpp"
#include "behaviours/stand/stand.hpp"
#include "robot/hal/hardware_link.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/runtime/nao_io_modules.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride {
namespace {

using behaviours::AnkleStrategyParameters;
using behaviours::HipStrategyParameters;
using hal::index;
using hal::JointId;

// A torso held at a fixed lean with a constant gyro offset.
class LeaningLink final : public hal::HardwareLink {
 public:
  bool read(hal::SensorFrame& s) override {
    s.time = n_++ * 0.01;
    s.angles = {roll, pitch};
    s.gyroscope = {gyro_bias_x, gyro_bias_y, 0};
    s.accelerometer = {0, 0, 9.81};
    return true;
  }
  void write(const hal::ActuatorFrame& a) override { last = a; }
  double period() const override { return 0.01; }
  std::string name() const override { return "leaning"; }

  double pitch = 0.1;   // forward
  double roll = -0.05;  // to the left
  double gyro_bias_x = 0.02;
  double gyro_bias_y = -0.314;  // the thesis' -18 deg/s
  hal::ActuatorFrame last;

 private:
  int n_ = 0;
};

// Stands the walking way: the stand posture with the left foot placed ahead.
class FakeWalking final : public Module {
 public:
  explicit FakeWalking(ModuleContext& c) : out_(c.provide<WalkingJointRequest>()) {}
  void update() override {
    out_.position = behaviours::stand_posture(behaviours::StandParameters{});
    out_.position[index(JointId::LHipPitch)] -= 0.2;  // left thigh forward
    out_.position[index(JointId::LAnklePitch)] += 0.2;
    out_.stiffness.fill(0.9);
  }

 private:
  WalkingJointRequest& out_;
};

ModuleRegistry posture_registry() {
  ModuleRegistry r;
  register_nao_io_modules(r);
  behaviours::register_posture_modules(r);
  r.add<FakeWalking>("FakeWalking");
  return r;
}

RuntimeConfig posture_config() {
  RuntimeConfig c;
  c.providers = {{"JointRequest", "WalkingJointRequestAssembler"},
                 {"PostureCorrectedRequest", "HipStrategy"}};
  return c;
}

int position_of(const std::vector<std::string>& order, const std::string& name) {
  return static_cast<int>(std::find(order.begin(), order.end(), name) - order.begin());
}

TEST(PostureModules, PlanRunsCalibrationEstimatorStrategyArmsThenAssembler) {
  const ModuleRegistry registry = posture_registry();
  LeaningLink link;
  Runtime rt(registry, posture_config(), link);
  const auto& order = rt.module_order();
  for (const char* m : {"GyroCalibration", "TorsoStateEstimator", "HipStrategy", "ArmSwing",
                        "WalkingJointRequestAssembler", "ActuatorConversion"})
    ASSERT_LT(position_of(order, m), static_cast<int>(order.size())) << m;
  EXPECT_LT(position_of(order, "GyroCalibration"), position_of(order, "TorsoStateEstimator"));
  EXPECT_LT(position_of(order, "TorsoStateEstimator"), position_of(order, "HipStrategy"));
  EXPECT_LT(position_of(order, "HipStrategy"), position_of(order, "WalkingJointRequestAssembler"));
  EXPECT_LT(position_of(order, "ArmSwing"), position_of(order, "WalkingJointRequestAssembler"));
  auto available = rt.providers_available("PostureCorrectedRequest");
  std::sort(available.begin(), available.end());
  EXPECT_EQ(available,
            (std::vector<std::string>{"AnkleStrategy", "HipStrategy", "NoPostureControl"}));
}

TEST(PostureModules, LeaningTorsoIsEstimatedAndCorrectedAndStrategiesSwapMidRun) {
  const ModuleRegistry registry = posture_registry();
  LeaningLink link;
  Runtime rt(registry, posture_config(), link);
  rt.set_parameters("GyroCalibration", "start_at_first_sample=false");  // C from 0, Eq. 4.2
  const int frames = 3000;  // 30 s: the gyro offset is (1 - 0.001)^3000 = 5 % of its start
  for (int i = 0; i < frames; ++i) ASSERT_TRUE(rt.step());
  const auto& gyro = rt.representation<CalibratedGyro>();
  EXPECT_NEAR(gyro.offset.y(), -0.314 * (1 - std::pow(0.999, frames)), 1e-9);  // Eq. 4.2
  EXPECT_NEAR(gyro.rate.y(), -0.314 * std::pow(0.999, frames), 1e-9);          // Eq. 4.4
  const auto& torso = rt.representation<TorsoState>();
  EXPECT_NEAR(torso.pitch, 0.1, 1e-3);
  EXPECT_NEAR(torso.roll, -0.05, 1e-3);

  const auto& reference = rt.representation<WalkingJointRequest>().position;
  const auto& request = rt.representation<JointRequest>().position;
  const auto expected_delta = [&](const auto& params) {
    return Eigen::Vector2d(params.kp_pitch * -torso.pitch + params.kd_pitch * -torso.pitch_rate,
                           params.kp_roll * -torso.roll + params.kd_roll * -torso.roll_rate);
  };
  const int lhp = index(JointId::LHipPitch), rhr = index(JointId::RHipRoll);
  const int lap = index(JointId::LAnklePitch), rar = index(JointId::RAnkleRoll);
  Eigen::Vector2d d = expected_delta(HipStrategyParameters{});
  EXPECT_NEAR(request[lhp] - reference[lhp], d[0], 1e-12);  // Eq. 4.10
  EXPECT_NEAR(request[rhr] - reference[rhr], d[1], 1e-12);  // Eq. 4.11
  EXPECT_LT(request[lhp], reference[lhp]);                  // forward lean: hip pitch down
  EXPECT_GT(request[rhr], reference[rhr]);                  // left lean: hip roll up
  EXPECT_EQ(request[lap], reference[lap]);
  EXPECT_EQ(link.last.position[lhp], request[lhp]);

  rt.swap_provider("PostureCorrectedRequest", "AnkleStrategy");
  ASSERT_TRUE(rt.step());
  d = expected_delta(AnkleStrategyParameters{});
  EXPECT_EQ(request[lhp], reference[lhp]);
  EXPECT_NEAR(request[lap] - reference[lap], d[0], 1e-12);  // Eq. 4.14
  EXPECT_NEAR(request[rar] - reference[rar], d[1], 1e-12);  // Eq. 4.15
  EXPECT_NEAR(rt.representation<PostureCorrectedRequest>().pitch_correction, d[0], 1e-12);

  rt.swap_provider("PostureCorrectedRequest", "NoPostureControl");
  ASSERT_TRUE(rt.step());
  for (const int j : {lhp, rhr, lap, rar}) EXPECT_EQ(request[j], reference[j]);

  rt.swap_provider("PostureCorrectedRequest", "default");
  ASSERT_TRUE(rt.step());
  EXPECT_LT(request[lhp], reference[lhp]);  // hip strategy again
  EXPECT_EQ(request[lap], reference[lap]);
}

TEST(PostureModules, GyroOffsetStartsAtTheFirstSampleByDefault) {
  const ModuleRegistry registry = posture_registry();
  LeaningLink link;
  Runtime rt(registry, posture_config(), link);
  const auto& gyro = rt.representation<CalibratedGyro>();
  ASSERT_TRUE(rt.step());
  EXPECT_NEAR(gyro.offset.x(), link.gyro_bias_x, 1e-15);  // not the (1 - 0.999) of a start at 0
  EXPECT_NEAR(gyro.offset.y(), link.gyro_bias_y, 1e-15);
  EXPECT_NEAR(gyro.rate.norm(), 0, 1e-15);
  // A new bias is then followed at the thesis' rate: half of it after ln 2 / alpha frames.
  link.gyro_bias_y = 0;
  for (int i = 0; i < 693; ++i) ASSERT_TRUE(rt.step());
  EXPECT_NEAR(gyro.offset.y(), -0.314 * std::pow(0.999, 693), 1e-12);  // Eq. 4.2
  EXPECT_NEAR(gyro.offset.y(), -0.157, 2e-4);
  EXPECT_NEAR(gyro.offset.x(), link.gyro_bias_x, 1e-15);
}

TEST(PostureModules, ArmSwingMovesTheArmAgainstTheForwardLeg) {
  const ModuleRegistry registry = posture_registry();
  LeaningLink link;
  RuntimeConfig config = posture_config();
  config.providers["PostureCorrectedRequest"] = "NoPostureControl";
  Runtime rt(registry, config, link);
  ASSERT_TRUE(rt.step());
  const auto& reference = rt.representation<WalkingJointRequest>().position;
  const auto& request = rt.representation<JointRequest>().position;
  const auto& arms = rt.representation<ArmSwingRequest>();
  const int lsp = index(JointId::LShoulderPitch), rsp = index(JointId::RShoulderPitch);
  EXPECT_LT(arms.left_arm_displacement, 0);  // left foot is ahead
  EXPECT_NEAR(arms.left_arm_displacement, -arms.right_arm_displacement, 1e-15);
  EXPECT_GT(request[lsp], reference[lsp]);  // left arm back
  EXPECT_LT(request[rsp], reference[rsp]);  // right arm forward
  EXPECT_EQ(request[lsp], arms.left_shoulder_pitch);
  rt.set_parameters("ArmSwing", "gain_scale=0");
  ASSERT_TRUE(rt.step());
  EXPECT_EQ(request[lsp], reference[lsp]);
  EXPECT_EQ(request[rsp], reference[rsp]);
}

}  // namespace
}  // namespace stride
