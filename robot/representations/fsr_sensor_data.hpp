#pragma once
// Foot pressure: the 8 FSR forces, per-foot totals and centres of pressure.
#include <Eigen/Core>

#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride {

struct FsrSensorData {
  std::array<double, hal::kNumFsr> force{};  // LoLA FSR order
  double total_left = 0;
  double total_right = 0;
  bool contact_left = false;  // total above the contact threshold
  bool contact_right = false;
  Eigen::Vector2d cop_left = Eigen::Vector2d::Zero();  // left ankle frame (x, y), 0 without contact
  Eigen::Vector2d cop_right = Eigen::Vector2d::Zero();  // right ankle frame
  // Overall CoP in the torso frame: both feet's CoPs through leg forward kinematics, weighted
  // by their forces; valid when any force is measured.
  Eigen::Vector3d cop_torso = Eigen::Vector3d::Zero();
  bool cop_torso_valid = false;

  static constexpr std::string_view kTypeName = "FsrSensorData";
  static constexpr auto fields() {
    using F = FsrSensorData;
    return std::make_tuple(
        field("force", &F::force, "N"), field("total_left", &F::total_left, "N"),
        field("total_right", &F::total_right, "N"), field("contact_left", &F::contact_left),
        field("contact_right", &F::contact_right), field("cop_left", &F::cop_left, "m"),
        field("cop_right", &F::cop_right, "m"), field("cop_torso", &F::cop_torso, "m"),
        field("cop_torso_valid", &F::cop_torso_valid));
  }
};

}  // namespace stride
