#pragma once
// NAO-like servos on a RobotBody: a velocity-servo position controller (opt-in: with gear play,
// or a compliant spring-damper instead) whose torque is bounded by stiffness x the motor's
// speed-dependent torque, or a direct torque command.
#include <vector>

#include "robot/hal/actuator_frame.hpp"
#include "simulator/scene/device_description.hpp"
#include "simulator/world/robot_body.hpp"

namespace stride::sim {

struct ServoCommand {
  hal::ServoMode mode = hal::ServoMode::Position;
  double position = 0;   // rad
  double stiffness = 1;  // 0..1
  double torque = 0;     // N*m, Torque mode
};

class ServoBank {
 public:
  // One servo per joint named in the device file; joints without a servo are passive.
  // step: the physics step (s), which the compliant servo's implicit spring needs.
  ServoBank(const RobotBody& body, const DeviceDescription& devices, double step);

  int servo_of_joint(int model_joint) const { return servo_of_joint_[model_joint]; }
  int count() const { return static_cast<int>(joints_.size()); }
  int joint(int servo) const { return joints_[servo]; }
  ServoCommand& command(int servo) { return commands_[servo]; }
  const ServoCommand& command(int servo) const { return commands_[servo]; }
  // The motor's stall torque at the joint (N m), the most a servo ever applies.
  double stall_torque(int servo) const { return motors_[servo]->stall_torque; }
  // The joint's true angle minus what the servo and its encoder take it to be (rad).
  double offset(int servo) const { return offsets_[servo]; }

  // Before each physics step: set the joint motors / torques from the commands.
  void apply(RobotBody& body);
  // After each physics step: accumulate motor torque for the current estimate.
  void measure(const RobotBody& body);
  // Mean |armature current| since the last call (A), per servo; resets the accumulation.
  void take_mean_currents(std::vector<double>& out);

 private:
  // Velocity servo through gear play: returns false while the joint is free within the play.
  bool apply_with_backlash(RobotBody& body, std::size_t servo, double q, double target);

  double step_;
  std::vector<int> joints_;  // model joint index per servo
  std::vector<const MotorSpec*> motors_;
  std::vector<int> servo_of_joint_;
  std::vector<ServoCommand> commands_;
  std::vector<double> offsets_;         // rad per servo, ServoSpec::offset
  std::vector<double> applied_torque_;  // torque-mode torque of the current step
  std::vector<double> gear_angle_;      // gear output angle per servo (rad), for backlash
  std::vector<double> error_integral_;  // rad*s per servo, for the spring's integral action
  std::vector<double> current_sum_;
  int samples_ = 0;
};

}  // namespace stride::sim
