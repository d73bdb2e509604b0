#pragma once
// IMU readings in the torso frame.
#include <Eigen/Core>

#include "robot/framework/reflect.hpp"

namespace stride {

struct InertialSensorData {
  STRIDE_FIELDS(InertialSensorData);
  STRIDE_FIELD(Eigen::Vector3d, acc, "m/s^2") = Eigen::Vector3d::Zero();
  STRIDE_FIELD(Eigen::Vector3d, gyro, "rad/s") = Eigen::Vector3d::Zero();
  // torso roll (x), pitch (y)
  STRIDE_FIELD(Eigen::Vector2d, angles, "rad") = Eigen::Vector2d::Zero();

  static constexpr std::string_view kTypeName = "InertialSensorData";
};

}  // namespace stride
