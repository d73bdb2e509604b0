#include "behaviours/stand/stand.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "robot/representations/frame_info.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"

namespace stride::behaviours {

using hal::index;
using hal::JointId;

std::array<double, hal::kNumJoints> stand_posture(const StandParameters& p) {
  std::array<double, hal::kNumJoints> q{};
  for (auto [hip, knee, ankle] :
       {std::array{JointId::LHipPitch, JointId::LKneePitch, JointId::LAnklePitch},
        std::array{JointId::RHipPitch, JointId::RKneePitch, JointId::RAnklePitch}}) {
    q[index(hip)] = p.hip_pitch;
    q[index(knee)] = p.knee_pitch;
    q[index(ankle)] = p.ankle_pitch;
  }
  q[index(JointId::LShoulderPitch)] = q[index(JointId::RShoulderPitch)] = p.shoulder_pitch;
  q[index(JointId::LShoulderRoll)] = p.shoulder_roll;
  q[index(JointId::RShoulderRoll)] = -p.shoulder_roll;
  q[index(JointId::LElbowYaw)] = p.elbow_yaw;
  q[index(JointId::RElbowYaw)] = -p.elbow_yaw;
  q[index(JointId::LElbowRoll)] = p.elbow_roll;
  q[index(JointId::RElbowRoll)] = -p.elbow_roll;
  return q;
}

namespace {

class Stand final : public Module {
 public:
  explicit Stand(ModuleContext& c)
      : frame_(c.require<FrameInfo>()),
        joints_(c.require<JointSensorData>()),
        params_(c.parameters<StandParameters>()),
        request_(c.provide<JointRequest>()) {}

  void update() override {
    if (!started_) {
      start_ = joints_.position;
      started_ = true;
    }
    elapsed_ += frame_.period;
    const double s =
        params_.interpolation_time > 0 ? std::min(1.0, elapsed_ / params_.interpolation_time) : 1.0;
    const double blend = 0.5 - 0.5 * std::cos(std::numbers::pi * s);  // zero velocity at both ends
    const auto target = stand_posture(params_);
    for (int i = 0; i < hal::kNumJoints; ++i) {
      request_.mode[i] = hal::ServoMode::Position;
      request_.position[i] = start_[i] + blend * (target[i] - start_[i]);
      request_.stiffness[i] = params_.stiffness;
      request_.torque[i] = 0;
    }
  }

 private:
  const FrameInfo& frame_;
  const JointSensorData& joints_;
  const StandParameters& params_;
  JointRequest& request_;
  bool started_ = false;
  double elapsed_ = 0;
  std::array<double, hal::kNumJoints> start_{};
};

}  // namespace

void register_stand(ModuleRegistry& registry) {
  registry.add<Stand>("Stand");
}

}  // namespace stride::behaviours
