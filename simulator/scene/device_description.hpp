#pragma once
// What a robot's devices are and how they behave, from the device file next to its URDF.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace stride::sim {

// A brushed DC motor with its gear, seen from the joint.
struct MotorSpec {
  std::string name;
  double ratio = 1;               // joint value = motor value / ratio
  double stall_torque = 1;        // N*m at the joint, at stiffness 1 and zero speed
  double no_load_speed = 5;       // rad/s at the joint
  double torque_constant = 0.01;  // N*m/A at the motor shaft
  double gain = 100;              // 1/s: target joint speed per radian of position error
  // Opt-in compliant position servo: torque = spring * error - damping * speed (bounded as
  // above) instead of the stiff velocity servo. 0 keeps the velocity servo.
  double spring = 0;   // N*m/rad at the joint, at stiffness 1
  double damping = 0;  // N*m*s/rad at the joint; 0 with a spring: back-EMF_damping()
  // Opt-in integral action of the compliant servo (the thesis' local PID joint controllers,
  // Sec. 3.6): torque += integral * (time integral of the error), held within the stall torque.
  double integral = 0;  // N*m/(rad*s) at the joint, at stiffness 1; needs a spring
  // Opt-in gear play of the velocity servo: the joint moves freely within +-backlash/2 of the
  // gear's output, which the servo drives; 0: no play.
  double backlash = 0;  // rad
  // A voltage-driven DC motor brakes with its back-EMF: stall torque over no-load speed.
  double back_emf_damping() const { return stall_torque / no_load_speed; }
  double spring_damping() const { return damping > 0 ? damping : back_emf_damping(); }
};

// A scene's change to one motor of the robot's device file: <motor name="..." gain="50"/> inside
// <robot>. Values in SI units by attribute name (the <motor> attributes of the device file).
struct MotorOverride {
  std::string name;
  std::map<std::string, double> values;
  std::string file;  // where it was written
  int line = 0;
};

// A scene's change to one servo of the device file, inside <robot>: a calibration error
// (<servo joint="..." offset="3deg"/>) and/or that joint's own copy of its motor with some
// <motor> attributes changed (<servo joint="LHipRoll" spring="400"/>), the other joints on the
// motor left as they are.
struct ServoOverride {
  std::string joint;
  std::optional<double> offset;         // rad; unset: the device file's
  std::map<std::string, double> motor;  // <motor> attributes, SI units, by name
  std::string file;                     // where it was written
  int line = 0;
};

// <calibration sd="0.5deg" [joints="LHipPitch RKneePitch ..."]/> in a scene's <robot>: each named
// servo (default: every leg servo) gets a zero error drawn from N(0, sd) with the scene seed, so a
// batch of walks over seeds meets a differently calibrated robot each time, as the thesis' NAO
// stood differently each time from its joints' zero positions (Sec. 4.3.2).
struct CalibrationSpread {
  double sd = 0;                    // rad
  std::vector<std::string> joints;  // empty: the leg servos
  std::string file;                 // where it was written
  int line = 0;
};

struct ServoSpec {
  std::string joint;  // URDF joint name
  int motor = -1;     // index into DeviceDescription::motors
  // Opt-in calibration error: the joint's true angle is the servo's (and its encoder's) angle plus
  // this, so a command q puts the joint at q + offset while the encoder reads q.
  double offset = 0;  // rad
};

struct ImuSpec {
  std::string link = "torso";
  Eigen::Vector3d accelerometer_at = Eigen::Vector3d::Zero();  // link frame
  Eigen::Vector3d gyroscope_at = Eigen::Vector3d::Zero();
  double accel_noise = 0;                                // std dev, m/s^2
  double gyro_noise = 0;                                 // std dev, rad/s
  double angle_noise = 0;                                // std dev, rad
  Eigen::Vector3d gyro_bias = Eigen::Vector3d::Zero();   // rad/s, added always
  Eigen::Vector3d accel_bias = Eigen::Vector3d::Zero();  // m/s^2
  double accel_range = 2 * 9.81;                         // saturation, m/s^2
  double gyro_range = 8.7266;                            // saturation, rad/s (500 deg/s)
  int delay_frames = 0;  // control frames between sampling and delivery
};

struct FsrSpec {
  std::string link;                          // foot link
  std::array<std::string, 4> names;          // FL, FR, RL, RR
  std::array<Eigen::Vector2d, 4> positions;  // link frame x, y
  double sole_z = 0;                         // link-frame height of the sole plane
  double noise = 0;                          // std dev, N
  double max_force = 25;                     // N, saturation
};

struct EncoderSpec {
  int bits = 12;     // quantisation over one turn
  double noise = 0;  // std dev, rad
};

struct DeviceDescription {
  std::string file;
  double period = 0.01;  // s, sensor/actuator cycle
  std::vector<MotorSpec> motors;
  std::vector<ServoSpec> servos;
  EncoderSpec encoder;
  ImuSpec imu;
  std::vector<FsrSpec> fsrs;  // two feet: left then right
};

// Throws stride::Error("file:line: ...").
DeviceDescription load_device_file(const std::string& path);

// Sets the override's values on the motor it names; throws stride::Error("file:line: ...") at
// the override when the device file has no such motor or the result is inconsistent.
void apply_motor_override(DeviceDescription& devices, const MotorOverride& override_);

// Sets the override's offset on the servo of its joint and gives that servo its own copy of its
// motor with the override's attributes; throws stride::Error("file:line: ...") at the override,
// changing nothing, when the device file has no servo for that joint or the motor is inconsistent.
void apply_servo_override(DeviceDescription& devices, const ServoOverride& override_);

}  // namespace stride::sim
