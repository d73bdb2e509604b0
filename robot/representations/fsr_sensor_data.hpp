#pragma once
// Foot pressure: the 8 FSR forces, per-foot totals and centres of pressure.
#include <Eigen/Core>

#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct FsrSensorData {
  STRIDE_FIELDS(FsrSensorData);
  STRIDE_FIELD((std::array<double, hal::kNumFsr>), force, "N"){};  // LoLA FSR order
  STRIDE_FIELD(double, total_left, "N") = 0;
  STRIDE_FIELD(double, total_right, "N") = 0;
  STRIDE_FIELD(bool, contact_left) = false;  // total above the contact threshold
  STRIDE_FIELD(bool, contact_right) = false;
  // left ankle frame (x, y), 0 without contact
  STRIDE_FIELD(Eigen::Vector2d, cop_left, "m") = Eigen::Vector2d::Zero();
  STRIDE_FIELD(Eigen::Vector2d, cop_right, "m") = Eigen::Vector2d::Zero();  // right ankle frame
  // Overall CoP in the torso frame: both feet's CoPs through leg forward kinematics, weighted
  // by their forces; valid when any force is measured.
  STRIDE_FIELD(Eigen::Vector3d, cop_torso, "m") = Eigen::Vector3d::Zero();
  STRIDE_FIELD(bool, cop_torso_valid) = false;

  static constexpr std::string_view kTypeName = "FsrSensorData";
};

}  // namespace stride
