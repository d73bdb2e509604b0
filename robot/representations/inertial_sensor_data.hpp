#pragma once
// IMU readings in the torso frame.
#include <Eigen/Core>

#include "robot/framework/reflect.hpp"

namespace stride {

struct InertialSensorData {
  Eigen::Vector3d acc = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro = Eigen::Vector3d::Zero();
  Eigen::Vector2d angles = Eigen::Vector2d::Zero();  // torso roll (x), pitch (y)

  static constexpr std::string_view kTypeName = "InertialSensorData";
  static constexpr auto fields() {
    using I = InertialSensorData;
    return std::make_tuple(field("acc", &I::acc, "m/s^2"), field("gyro", &I::gyro, "rad/s"),
                           field("angles", &I::angles, "rad"));
  }
};

}  // namespace stride
