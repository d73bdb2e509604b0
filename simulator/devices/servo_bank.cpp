#include "simulator/devices/servo_bank.hpp"

#include <algorithm>
#include <cmath>

#include "robot/core/error.hpp"

namespace stride::sim {

ServoBank::ServoBank(const RobotBody& body, const DeviceDescription& devices, double step)
    : step_(step) {
  const auto& model = body.model();
  servo_of_joint_.assign(model.joints.size(), -1);
  for (const ServoSpec& s : devices.servos) {
    const int j = model.joint_index(s.joint);
    if (j < 0 || !model.joints[j].movable())
      throw Error(devices.file + ": servo for '" + s.joint + "', which is not a movable joint of " +
                  model.source);
    servo_of_joint_[j] = static_cast<int>(joints_.size());
    joints_.push_back(j);
    motors_.push_back(&devices.motors[s.motor]);
    offsets_.push_back(s.offset);
  }
  commands_.resize(joints_.size());
  for (int j : joints_) gear_angle_.push_back(body.joint_position(j));
  applied_torque_.assign(joints_.size(), 0);
  error_integral_.assign(joints_.size(), 0);
  current_sum_.assign(joints_.size(), 0);
}

void ServoBank::apply(RobotBody& body) {
  for (size_t s = 0; s < joints_.size(); ++s) {
    const int j = joints_[s];
    if (!body.is_hinge(j)) continue;
    const MotorSpec& m = *motors_[s];
    const ServoCommand& c = commands_[s];
    const double q = body.joint_position(j);
    body.keep_stops_within_reach(j, q);
    const double qd = body.joint_velocity(j);
    // A DC motor's torque falls linearly with speed; keep a floor so it can always brake.
    const double speed_factor = std::clamp(1.0 - std::abs(qd) / m.no_load_speed, 0.25, 1.0);
    const double max_torque = m.stall_torque * speed_factor;
    if (c.mode == hal::ServoMode::Position) {
      const double target = c.position + offsets_[s];  // where the joint really goes
      const double err = target - q;
      bool engaged = true;
      if (m.backlash > 0) {
        engaged = apply_with_backlash(body, s, q, target);
      } else if (m.spring > 0) {
        // ODE's soft motor row: torque = spring * (err - step * speed) - damping * speed, the
        // spring taken at the end of the step so that stiff springs stay stable.
        const double softness = 1.0 / (step_ * m.spring + m.spring_damping());
        double integral_torque = 0;
        // The integral stays within the stall torque and is cleared while unpowered: no wind-up.
        if (m.integral > 0) {
          const double limit = m.stall_torque / m.integral;
          error_integral_[s] =
              c.stiffness > 0 ? std::clamp(error_integral_[s] + err * step_, -limit, limit) : 0;
          integral_torque = m.integral * error_integral_[s];
        }
        body.set_motor_speed(j, (m.spring * err + integral_torque) * softness);
        body.set_motor_softness(j, softness);
      } else {
        body.set_motor_speed(j, std::clamp(m.gain * err, -m.no_load_speed, m.no_load_speed));
      }
      body.set_motor_max_torque(j, engaged ? std::clamp(c.stiffness, 0.0, 1.0) * max_torque : 0.0);
      applied_torque_[s] = 0;
    } else {
      body.set_motor_max_torque(j, 0);
      gear_angle_[s] = q;  // back-driven with the joint
      error_integral_[s] = 0;
      const double tau = std::clamp(c.torque, -max_torque, max_torque);
      body.add_joint_torque(j, tau);
      applied_torque_[s] = tau;
    }
  }
}

bool ServoBank::apply_with_backlash(RobotBody& body, std::size_t s, double q, double target) {
  const MotorSpec& m = *motors_[s];
  // The gear's output follows the command at the servo's speed; the joint sits in its play.
  double& gear = gear_angle_[s];
  const double gear_speed = std::clamp(m.gain * (target - gear), -m.no_load_speed, m.no_load_speed);
  gear += gear_speed * step_;
  const double half = 0.5 * m.backlash;
  const double from_gear = q - gear;
  if (std::abs(from_gear) <= half) return false;               // free within the play
  const double tooth = gear + std::copysign(half, from_gear);  // the flank the joint pushes on
  body.set_motor_speed(joints_[s], std::clamp(gear_speed + m.gain * (tooth - q),
                                              -2 * m.no_load_speed, 2 * m.no_load_speed));
  return true;
}

void ServoBank::measure(const RobotBody& body) {
  for (size_t s = 0; s < joints_.size(); ++s) {
    const MotorSpec& m = *motors_[s];
    const double tau = commands_[s].mode == hal::ServoMode::Position
                           ? body.joint_constraint_torque(joints_[s])
                           : applied_torque_[s];
    current_sum_[s] += std::abs(tau) / (m.ratio * m.torque_constant);
  }
  ++samples_;
}

void ServoBank::take_mean_currents(std::vector<double>& out) {
  out.resize(joints_.size());
  for (size_t s = 0; s < joints_.size(); ++s) {
    out[s] = samples_ ? current_sum_[s] / samples_ : 0.0;
    current_sum_[s] = 0;
  }
  samples_ = 0;
}

}  // namespace stride::sim
