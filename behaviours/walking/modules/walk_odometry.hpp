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
  double x = 0.0;              // m, the torso's place from where the estimate started
  double y = 0.0;              // m
  double yaw = 0.0;            // rad, the torso's yaw: gyro z integrated, times gyro_scale
  double gyro_yaw = 0.0;       // rad, the gyro's z integral as read
  std::int64_t support = 0;    // 0 none yet, 1 left, 2 right
  std::int64_t exchanges = 0;  // support exchanges counted

  static constexpr std::string_view kTypeName = "WalkOdometry";
  static constexpr auto fields() {
    using W = WalkOdometry;
    return std::make_tuple(field("x", &W::x, "m"), field("y", &W::y, "m"),
                           field("yaw", &W::yaw, "rad"), field("gyro_yaw", &W::gyro_yaw, "rad"),
                           field("support", &W::support), field("exchanges", &W::exchanges));
  }
};

struct WalkOdometryParameters {
  double gyro_scale = 1.0;      // the gyro z integral's calibration
  double exchange_share = 0.7;  // share of both feet's load that makes a foot the support

  static constexpr std::string_view kTypeName = "WalkOdometryParameters";
  static constexpr auto fields() {
    using P = WalkOdometryParameters;
    return std::make_tuple(field("gyro_scale", &P::gyro_scale, "", Range{0.5, 2}),
                           field("exchange_share", &P::exchange_share, "", Range{0.5, 1}));
  }
};

}  // namespace stride

namespace stride::behaviours {
void register_walk_odometry_modules(ModuleRegistry& registry);
}  // namespace stride::behaviours
