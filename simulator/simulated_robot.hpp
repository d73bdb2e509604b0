#pragma once
// One robot in the world with its devices: its sensors sampled at each control frame, its servos
// following the commands written to it (the Simulation hands the one to the robot's controller and
// writes the other, hal::FrameController).
#include <array>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "robot/hal/actuator_frame.hpp"
#include "robot/hal/sensor_frame.hpp"
#include "robot/model/robot_model.hpp"
#include "simulator/devices/fsr_device.hpp"
#include "simulator/devices/imu_device.hpp"
#include "simulator/devices/servo_bank.hpp"
#include "simulator/scene/device_description.hpp"
#include "simulator/scene/scene_description.hpp"
#include "simulator/world/physics_world.hpp"
#include "simulator/world/robot_body.hpp"

namespace stride::sim {

struct TorsoPose {
  double x = 0, y = 0, z = 0, roll = 0, pitch = 0, yaw = 0;
};

class SimulatedRobot {
 public:
  // Loads the URDF and device file named by `placement`; throws stride::Error naming file:line.
  SimulatedRobot(PhysicsWorld& world, const RobotPlacement& placement, int index,
                 std::uint64_t scene_seed);

  // The commands its servos follow from now on. Throws stride::Error naming the joint for a
  // non-finite value (a controller bug).
  void write(const hal::ActuatorFrame& in);
  double period() const { return devices_.period; }  // control period, s
  std::string name() const { return placement_.name; }

  void before_physics_step();
  void after_physics_step(const PhysicsWorld& world);
  // Closes the control frame that ends at `time`: samples every sensor.
  void sample_sensors(double time, const Eigen::Vector3d& gravity);

  const model::RobotModel& model() const { return *model_; }
  const RobotBody& body() const { return *body_; }
  // Mutable access for what moves the bodies from outside: pushes, the teleport, tests.
  RobotBody& mutable_body() { return *body_; }
  const DeviceDescription& devices() const { return devices_; }
  const RobotPlacement& placement() const { return placement_; }
  // The zero errors <calibration> drew for this seed, by joint (empty without one).
  const std::vector<std::pair<std::string, double>>& calibration_errors() const {
    return calibration_errors_;
  }
  const hal::SensorFrame& latest_sensors() const { return delivered_; }
  // The true load on FSR foot `f` (device-file order: 0 left, 1 right) at each physics step of
  // the last control frame, before the sensors' sharing, noise and saturation; empty if none.
  const std::vector<double>& sole_loads(int f) const;
  const hal::ActuatorFrame& latest_commands() const { return commands_; }
  SensorSwitches& sensor_switches() { return switches_; }

  TorsoPose torso_pose() const;
  // Stall torque of the servo on model joint `joint` (N m); 0 for a joint without a servo.
  double max_joint_torque(int joint) const;
  bool fallen() const;
  // Model joint index of each LoLA joint, or -1 (hands).
  int joint_of_lola(int lola) const { return lola_to_joint_[lola]; }

 private:
  void apply_commands();

  RobotPlacement placement_;
  int index_;
  std::unique_ptr<model::RobotModel> model_;
  DeviceDescription devices_;
  std::unique_ptr<RobotBody> body_;
  std::unique_ptr<ServoBank> servos_;
  std::optional<ImuDevice> imu_;
  std::vector<FsrDevice> fsrs_;
  NoiseSource encoder_noise_;
  SensorSwitches switches_;
  std::array<int, hal::kNumJoints> lola_to_joint_{};
  hal::ActuatorFrame commands_;
  std::deque<ImuReading> imu_queue_;
  hal::SensorFrame delivered_;
  std::vector<double> currents_;
  std::vector<std::pair<std::string, double>> calibration_errors_;
};

}  // namespace stride::sim
