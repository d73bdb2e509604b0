#pragma once
// The last line before the motors, in every Runtime: positions clamped to the joint limits,
// stiffness to 0..1, and a NaN or infinite value replaced by that joint's last valid command
// (never 0 rad, which may be far from where the joint stands).
#include <array>

#include "robot/hal/actuator_frame.hpp"
#include "robot/hal/sensor_frame.hpp"
#include "robot/model/robot_model.hpp"
#include "robot/nao/joint_limits.hpp"
#include "robot/representations/command_safety.hpp"

namespace stride {

// Limits of the LoLA joints: the model's where it has the joint, else the NAO's published ones.
std::array<nao::JointRange, hal::kNumJoints> lola_joint_limits(const model::RobotModel* model);

class CommandGuard {
 public:
  explicit CommandGuard(const std::array<nao::JointRange, hal::kNumJoints>& limits)
      : limits_(limits) {}

  // Holds where the robot stands: the measured positions at the measured stiffness.
  void hold_measured(const hal::SensorFrame& s);
  // Makes `frame` safe in place, counting what changed; it becomes the last safe command.
  void apply(hal::ActuatorFrame& frame, CommandSafety& counts);
  const hal::ActuatorFrame& last_safe() const { return last_; }

 private:
  std::array<nao::JointRange, hal::kNumJoints> limits_;
  hal::ActuatorFrame last_;
};

}  // namespace stride
