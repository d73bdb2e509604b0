#include "robot/runtime/command_guard.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace stride {

std::array<nao::JointRange, hal::kNumJoints> lola_joint_limits(const model::RobotModel* model) {
  auto limits = nao::kJointLimits;
  if (!model) return limits;
  for (int i = 0; i < hal::kNumJoints; ++i) {
    const int j = model->joint_index(std::string(hal::kJointNames[i]));
    if (j >= 0 && model->joints[j].type == model::JointType::Revolute)
      limits[i] = {model->joints[j].lower, model->joints[j].upper};
  }
  return limits;
}

void CommandGuard::hold_measured(const hal::SensorFrame& s) {
  for (int i = 0; i < hal::kNumJoints; ++i) {
    last_.mode[i] = hal::ServoMode::Position;
    last_.position[i] = std::isfinite(s.position[i])
                            ? std::clamp(s.position[i], limits_[i].lower, limits_[i].upper)
                            : std::clamp(0.0, limits_[i].lower, limits_[i].upper);
    last_.stiffness[i] = std::isfinite(s.stiffness[i]) ? std::clamp(s.stiffness[i], 0.0, 1.0) : 0;
    last_.torque[i] = 0;
  }
}

void CommandGuard::apply(hal::ActuatorFrame& f, CommandSafety& counts) {
  for (int i = 0; i < hal::kNumJoints; ++i) {
    double& q = f.position[i];
    if (!std::isfinite(q)) {
      q = last_.position[i];
      ++counts.nonfinite_held;
    } else if (q < limits_[i].lower || q > limits_[i].upper) {
      q = std::clamp(q, limits_[i].lower, limits_[i].upper);
      ++counts.clamped_positions;
    }
    double& s = f.stiffness[i];
    if (!std::isfinite(s)) {
      s = last_.stiffness[i];
      ++counts.nonfinite_held;
    } else if (s < 0 || s > 1) {
      s = std::clamp(s, 0.0, 1.0);
      ++counts.clamped_stiffness;
    }
    if (f.mode[i] == hal::ServoMode::Torque && !std::isfinite(f.torque[i])) {
      // No valid torque to hold: the joint holds its last valid position instead.
      f.mode[i] = hal::ServoMode::Position;
      f.torque[i] = 0;
      ++counts.nonfinite_held;
    }
  }
  last_ = f;
}

}  // namespace stride
