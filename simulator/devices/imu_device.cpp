#include "simulator/devices/imu_device.hpp"

#include <algorithm>
#include <cmath>

#include "robot/core/error.hpp"

namespace stride::sim {

ImuDevice::ImuDevice(const RobotBody& body, const ImuSpec& spec, NoiseSource noise)
    : spec_(spec), link_(body.model().link_index(spec.link)), noise_(noise) {
  if (link_ < 0)
    throw Error("IMU link '" + spec.link + "' is not a link of " + body.model().source);
}

Eigen::Vector3d ImuDevice::point_velocity(const RobotBody& body, const Eigen::Vector3d& at) const {
  return body.point_velocity(link_, body.link_pose(link_) * at);
}

void ImuDevice::begin_frame(const RobotBody& body) {
  v_start_ = point_velocity(body, spec_.accelerometer_at);
}

ImuReading ImuDevice::sample(const RobotBody& body, double dt, const Eigen::Vector3d& gravity,
                             bool noise_on) {
  const Eigen::Isometry3d pose = body.link_pose(link_);
  const Eigen::Matrix3d rt = pose.linear().transpose();
  const Eigen::Vector3d v_end = point_velocity(body, spec_.accelerometer_at);
  const Eigen::Vector3d a = (v_end - v_start_) / dt;
  const Eigen::Vector3d specific_force = rt * (a - gravity) + spec_.accel_bias;
  const Eigen::Vector3d gyro = rt * body.link_angular_velocity(link_) + spec_.gyro_bias;
  ImuReading r;
  for (int i = 0; i < 3; ++i) {
    const double an = noise_on ? noise_.gaussian(spec_.accel_noise) : 0.0;
    const double gn = noise_on ? noise_.gaussian(spec_.gyro_noise) : 0.0;
    r.accelerometer[i] = std::clamp(specific_force[i] + an, -spec_.accel_range, spec_.accel_range);
    r.gyroscope[i] = std::clamp(gyro[i] + gn, -spec_.gyro_range, spec_.gyro_range);
  }
  // Roll and pitch of the torso relative to gravity (z-y-x Euler angles).
  const Eigen::Matrix3d& m = pose.linear();
  const double roll = std::atan2(m(2, 1), m(2, 2));
  const double pitch = std::atan2(-m(2, 0), std::hypot(m(2, 1), m(2, 2)));
  r.angles[0] = roll + (noise_on ? noise_.gaussian(spec_.angle_noise) : 0.0);
  r.angles[1] = pitch + (noise_on ? noise_.gaussian(spec_.angle_noise) : 0.0);
  v_start_ = v_end;
  return r;
}

}  // namespace stride::sim
