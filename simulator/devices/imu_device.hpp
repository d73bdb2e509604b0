#pragma once
// Torso IMU: accelerometer (specific force, mean over the control frame), gyroscope, and the
// roll/pitch angles a NAO's IMU board reports; bias, white noise, saturation.
#include <array>

#include <Eigen/Core>

#include "simulator/scene/device_description.hpp"
#include "simulator/scene/noise_source.hpp"
#include "simulator/world/robot_body.hpp"

namespace stride::sim {

struct ImuReading {
  std::array<double, 3> accelerometer{};
  std::array<double, 3> gyroscope{};
  std::array<double, 2> angles{};
};

class ImuDevice {
 public:
  ImuDevice(const RobotBody& body, const ImuSpec& spec, NoiseSource noise);
  // Start of a control frame: remember the accelerometer point's velocity.
  void begin_frame(const RobotBody& body);
  // End of a control frame of length dt: the reading.
  ImuReading sample(const RobotBody& body, double dt, const Eigen::Vector3d& gravity,
                    bool noise_on);

 private:
  Eigen::Vector3d point_velocity(const RobotBody& body, const Eigen::Vector3d& at) const;
  ImuSpec spec_;
  int link_;
  NoiseSource noise_;
  Eigen::Vector3d v_start_ = Eigen::Vector3d::Zero();
};

}  // namespace stride::sim
