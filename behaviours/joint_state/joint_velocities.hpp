#pragma once
// Joint velocities for the torque-mode controllers of Chs. 5 and 6, which need q' and the NAO
// does not measure it: JointVelocityEstimator differentiates the encoder angles backwards over
// the control period (zero at the first frame).
//   FrameInfo, JointSensorData -> JointVelocities
#include <array>

#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct JointVelocities {
  STRIDE_FIELDS(JointVelocities);
  STRIDE_FIELD((std::array<double, hal::kNumJoints>), velocity, "rad/s"){};  // LoLA order

  static constexpr std::string_view kTypeName = "JointVelocities";
};

namespace behaviours {

// (q - q_before) / period, per joint.
std::array<double, hal::kNumJoints> backward_difference(
    const std::array<double, hal::kNumJoints>& before,
    const std::array<double, hal::kNumJoints>& now, double period);

void register_joint_state_modules(ModuleRegistry& registry);

}  // namespace behaviours
}  // namespace stride
