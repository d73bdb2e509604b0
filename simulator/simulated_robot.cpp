#include "simulator/simulated_robot.hpp"

#include <cmath>

#include "robot/core/error.hpp"
#include "robot/core/pose.hpp"
#include "robot/model/link_poses.hpp"
#include "robot/model/urdf_loader.hpp"
#include "simulator/devices/calibration_spread.hpp"

namespace stride::sim {
namespace {

// Lowest z of every collision shape with the root at `root` and joints at q.
double lowest_point(const model::RobotModel& m, const model::JointVector& q,
                    const Eigen::Isometry3d& root) {
  std::vector<Eigen::Isometry3d> poses;
  model::link_poses(m, q, poses);
  double low = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < m.links.size(); ++i)
    for (const auto& s : m.links[i].collisions) {
      const Eigen::Isometry3d t = root * poses[i] * s.origin;
      using Kind = model::CollisionShape::Kind;
      if (s.kind == Kind::Box) {
        for (int c = 0; c < 8; ++c) {
          const Eigen::Vector3d corner((c & 1 ? 0.5 : -0.5) * s.box_size.x(),
                                       (c & 2 ? 0.5 : -0.5) * s.box_size.y(),
                                       (c & 4 ? 0.5 : -0.5) * s.box_size.z());
          low = std::min(low, (t * corner).z());
        }
      } else if (s.kind == Kind::Sphere) {
        low = std::min(low, t.translation().z() - s.radius);
      } else {
        const double az = t.linear()(2, 2);
        low = std::min(low, t.translation().z() - std::abs(az) * s.length / 2 -
                                s.radius * std::sqrt(std::max(0.0, 1 - az * az)));
      }
    }
  return low;
}

}  // namespace

SimulatedRobot::SimulatedRobot(PhysicsWorld& world, const RobotPlacement& placement, int index,
                               std::uint64_t scene_seed)
    : placement_(placement),
      index_(index),
      encoder_noise_(NoiseSource::for_stream(scene_seed, placement.name + "/encoders")),
      switches_(placement.sensors) {
  try {
    model_ = std::make_unique<model::RobotModel>(model::load_urdf(placement.urdf));
    if (!placement.devices.empty()) devices_ = load_device_file(placement.devices);
    if (placement.period > 0) devices_.period = placement.period;  // the scene's choice wins
    for (const MotorOverride& o : placement.motors) apply_motor_override(devices_, o);
    for (const ServoOverride& o : placement.servos) apply_servo_override(devices_, o);
    if (placement.gyro_bias) devices_.imu.gyro_bias = *placement.gyro_bias;
    if (placement.calibration) {
      MimicJoints mimic;
      for (const auto& jt : model_->joints)
        if (jt.mimic_of >= 0)
          mimic[jt.name] = {model_->joints[jt.mimic_of].name, jt.mimic_multiplier};
      // Its own stream: adding a calibration leaves every other device's noise as it was.
      NoiseSource noise = NoiseSource::for_stream(scene_seed, placement.name + "/calibration");
      calibration_errors_ = draw_calibration_errors(devices_, *placement.calibration, mimic, noise);
    }
  } catch (const Error& e) {
    throw error_at(placement.file, placement.line,
                   "<robot name=\"" + placement.name + "\">: " + e.what());
  }
  model::JointVector q = model::zero_joints(*model_);
  for (const auto& [name, value] : placement.joints) {
    const int j = model_->joint_index(name);
    if (j < 0 || !model_->joints[j].movable())
      throw error_at(placement.file, placement.joints_line,
                     "<joints>: '" + name + "' is not a movable joint of " + placement.urdf);
    const auto& jt = model_->joints[j];
    if (jt.type == model::JointType::Revolute && (value < jt.lower || value > jt.upper))
      throw error_at(placement.file, placement.joints_line,
                     "<joints>: " + name + " = " + std::to_string(value) + " outside its limits [" +
                         std::to_string(jt.lower) + ", " + std::to_string(jt.upper) + "]");
    q[j] = value;
  }
  model::apply_mimic(*model_, q);
  Eigen::Isometry3d root = pose_from_xyz_rpy(placement.xyz, placement.rpy);
  if (placement.auto_height) root.translation().z() -= lowest_point(*model_, q, root);

  try {
    if (world.settings().engine == PhysicsSettings::Engine::Mujoco)
      for (const MotorSpec& m : devices_.motors)
        if (m.spring > 0)
          throw Error("motor '" + m.name +
                      "': a compliant (spring) servo has no counterpart on engine=\"mujoco\"");
    body_ = world.add_robot(*model_, index, root, q);
    if (placement.fixed_base) body_->fix_to_world();
    servos_ = std::make_unique<ServoBank>(*body_, devices_, world.settings().step);
    if (!placement.devices.empty()) {
      imu_.emplace(*body_, devices_.imu,
                   NoiseSource::for_stream(scene_seed, placement.name + "/imu"));
      for (const auto& f : devices_.fsrs)
        fsrs_.emplace_back(*body_, index, f,
                           NoiseSource::for_stream(scene_seed, placement.name + "/" + f.link));
    }
  } catch (const Error& e) {
    throw error_at(placement.file, placement.line,
                   "<robot name=\"" + placement.name + "\">: " + e.what());
  }

  for (int l = 0; l < hal::kNumJoints; ++l)
    lola_to_joint_[l] = model_->joint_index(std::string(hal::kJointNames[l]));
  for (int l = 0; l < hal::kNumJoints; ++l) {
    const int j = lola_to_joint_[l];
    commands_.mode[l] = hal::ServoMode::Position;
    commands_.position[l] = j >= 0 ? q[j] : 0.0;
    commands_.stiffness[l] = placement.stiffness;
  }
  // Joints outside the LoLA list (e.g. RHipYawPitch, a mimic) follow their master's command.
  for (int s = 0; s < servos_->count(); ++s) {
    servos_->command(s).position = q[servos_->joint(s)];
    servos_->command(s).stiffness = placement.stiffness;
  }
  apply_commands();
  sample_sensors(0.0, world.settings().gravity);
}

void SimulatedRobot::write(const hal::ActuatorFrame& in) {
  // A non-finite command would reach ODE's motor rows as NaN; it is a controller bug, named here.
  for (int l = 0; l < hal::kNumJoints; ++l)
    for (const auto& [what, v] :
         {std::pair{"position", in.position[l]}, std::pair{"stiffness", in.stiffness[l]},
          std::pair{"torque", in.torque[l]}})
      if (!std::isfinite(v))
        throw Error("robot '" + placement_.name + "': the controller commanded " +
                    std::string(hal::kJointNames[l]) + " " + what + " " + std::to_string(v) +
                    " (expected a finite value)");
  commands_ = in;
  apply_commands();
}

void SimulatedRobot::apply_commands() {
  for (int l = 0; l < hal::kNumJoints; ++l) {
    const int j = lola_to_joint_[l];
    if (j < 0) continue;
    const int s = servos_->servo_of_joint(j);
    if (s < 0) continue;
    ServoCommand& c = servos_->command(s);
    c.mode = commands_.mode[l];
    c.position = commands_.position[l];
    c.stiffness = commands_.stiffness[l];
    c.torque = commands_.torque[l];
  }
  // One motor drives both HipYawPitch joints: a mimic joint takes its master's command.
  const auto& m = *model_;
  for (int s = 0; s < servos_->count(); ++s) {
    const auto& jt = m.joints[servos_->joint(s)];
    if (jt.mimic_of < 0) continue;
    const int ms = servos_->servo_of_joint(jt.mimic_of);
    if (ms < 0) continue;
    ServoCommand c = servos_->command(ms);
    c.position = jt.mimic_multiplier * c.position + jt.mimic_offset;
    c.torque *= jt.mimic_multiplier;
    servos_->command(s) = c;
  }
}

void SimulatedRobot::before_physics_step() {
  servos_->apply(*body_);
}

void SimulatedRobot::after_physics_step(const PhysicsWorld& world) {
  servos_->measure(*body_);
  for (auto& f : fsrs_) f.accumulate(*body_, world);
}

void SimulatedRobot::sample_sensors(double time, const Eigen::Vector3d& gravity) {
  hal::SensorFrame s;
  s.time = time;
  servos_->take_mean_currents(currents_);
  const double resolution = 2 * M_PI / std::pow(2.0, devices_.encoder.bits);
  for (int l = 0; l < hal::kNumJoints; ++l) {
    const int j = lola_to_joint_[l];
    s.stiffness[l] = commands_.stiffness[l];
    s.temperature[l] = 30.0;
    if (j < 0) {  // hands are not simulated: they report their command
      s.position[l] = commands_.position[l];
      continue;
    }
    const int sv = servos_->servo_of_joint(j);
    double q = body_->joint_position(j) - (sv >= 0 ? servos_->offset(sv) : 0.0);
    if (switches_.noise) q += encoder_noise_.gaussian(devices_.encoder.noise);
    if (switches_.quantise) q = std::round(q / resolution) * resolution;
    s.position[l] = q;
    s.current[l] = sv >= 0 ? currents_[sv] : 0.0;
  }
  if (imu_) {
    const double dt = time > 0 ? devices_.period : 1.0;
    imu_queue_.push_back(imu_->sample(*body_, dt, gravity, switches_.noise));
    const size_t delay = switches_.delay ? static_cast<size_t>(devices_.imu.delay_frames) : 0;
    while (imu_queue_.size() > delay + 1) imu_queue_.pop_front();
    const ImuReading& r = imu_queue_.front();
    s.accelerometer = r.accelerometer;
    s.gyroscope = r.gyroscope;
    s.angles = r.angles;
    imu_->begin_frame(*body_);
  }
  for (size_t f = 0; f < fsrs_.size() && f < 2; ++f) {
    const auto v = fsrs_[f].sample(switches_.noise);
    for (int k = 0; k < 4; ++k) s.fsr[f * 4 + k] = v[k];
  }
  delivered_ = s;
}

const std::vector<double>& SimulatedRobot::sole_loads(int f) const {
  static const std::vector<double> kNone;
  return f >= 0 && f < static_cast<int>(fsrs_.size()) ? fsrs_[f].frame_loads() : kNone;
}

TorsoPose SimulatedRobot::torso_pose() const {
  const Eigen::Isometry3d t = body_->link_pose(model_->root_link);
  const Eigen::Matrix3d& m = t.linear();
  TorsoPose p;
  p.x = t.translation().x();
  p.y = t.translation().y();
  p.z = t.translation().z();
  p.roll = std::atan2(m(2, 1), m(2, 2));
  p.pitch = std::atan2(-m(2, 0), std::hypot(m(2, 1), m(2, 2)));
  p.yaw = std::atan2(m(1, 0), m(0, 0));
  return p;
}

bool SimulatedRobot::fallen() const {
  const TorsoPose p = torso_pose();
  return std::abs(p.roll) > placement_.fall_tilt || std::abs(p.pitch) > placement_.fall_tilt ||
         p.z < placement_.fall_height;
}

double SimulatedRobot::max_joint_torque(int joint) const {
  const int servo = servos_->servo_of_joint(joint);
  return servo < 0 ? 0.0 : servos_->stall_torque(servo);
}

}  // namespace stride::sim
