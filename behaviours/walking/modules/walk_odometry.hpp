#pragma once
// WalkOdometry: where the robot is from its own sensors (walking/odometry/leg_odometry.hpp),
// provided by WalkOdometryEstimator from the gyro, the joint encoders and the FSRs; the walks'
// heading and place holds read it.
//
// The gyro's z integral reads about a fifth low in simulation: the torso's yaw rate moves within
// each control frame with the servos' answer to the new commands, and the IMU samples it at the
// frame's end, where it is lowest (scenes/experiments/README.md, "walk requests"). gyro_scale
// is the calibration that takes it back (1: the gyro as read).
#include <array>
#include <cstdint>
#include <string_view>

#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"

namespace stride {

struct WalkOdometry {
  STRIDE_FIELDS(WalkOdometry);
  // m, the torso's place from where the estimate started
  STRIDE_FIELD(double, x, "m") = 0.0;
  STRIDE_FIELD(double, y, "m") = 0.0;
  // rad, the torso's yaw: gyro z integrated, times gyro_scale
  STRIDE_FIELD(double, yaw, "rad") = 0.0;
  STRIDE_FIELD(double, gyro_yaw, "rad") = 0.0;  // rad, the gyro's z integral as read
  STRIDE_FIELD(std::int64_t, support) = 0;      // 0 none yet, 1 left, 2 right
  STRIDE_FIELD(std::int64_t, exchanges) = 0;    // support exchanges counted

  static constexpr std::string_view kTypeName = "WalkOdometry";
};

struct WalkOdometryParameters {
  STRIDE_FIELDS(WalkOdometryParameters);
  // the gyro z integral's calibration
  STRIDE_FIELD(double, gyro_scale, "", Range{0.5, 2}) = 1.0;
  // share of both feet's load that makes a foot the support
  STRIDE_FIELD(double, exchange_share, "", Range{0.5, 1}) = 0.7;

  static constexpr std::string_view kTypeName = "WalkOdometryParameters";
};

}  // namespace stride

namespace stride::behaviours {
void register_walk_odometry_modules(ModuleRegistry& registry);
}  // namespace stride::behaviours
