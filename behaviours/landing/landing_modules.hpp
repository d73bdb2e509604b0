#pragma once
// Thesis Ch. 6 as modules: the left sole set down along a planned descent, by the position-
// controlled leg (LandingPosition: leg IK, the servos' position loop) or by the impedance law of
// the law of Eq. 6.17 in torque mode (LandingImpedance). Every other joint holds its first-frame
// angle.
//   LandingPosition   FrameInfo, JointSensorData -> JointRequest
//   LandingImpedance  FrameInfo, JointSensorData, JointVelocities, InertialSensorData
//                     -> JointRequest
// `mr JointRequest LandingImpedance` swaps one for the other; scenes/landing/landing_nao.xml
// chooses LandingImpedance; a sweep varies LandingImpedance.stiffness, .damping, .speed, ...
#include <Eigen/Core>

#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::behaviours {

// The plan: the sole keeps the pose it has at the first frame and sinks at `speed` by `descent`.
struct LandingPositionParameters {
  STRIDE_FIELDS(LandingPositionParameters);
  STRIDE_FIELD(double, speed, "m/s", Range{1e-3, 2}) = 0.2;
  // m below its starting height where the plan ends
  STRIDE_FIELD(double, descent, "m", Range{0, 0.2}) = 0.03;
  STRIDE_FIELD(double, hold_stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "LandingPositionParameters";
};

// The same plan, and the gains of Eq. 6.17 (translation in the torso frame's axes).
struct LandingImpedanceParameters {
  STRIDE_FIELDS(LandingImpedanceParameters);
  STRIDE_FIELD(double, speed, "m/s", Range{1e-3, 2}) = 0.2;
  STRIDE_FIELD(double, descent, "m", Range{0, 0.2}) = 0.03;
  STRIDE_FIELD(Eigen::Vector3d, stiffness, "N/m", Range{0, 1e6}){2000, 2000, 300};  // K, N/m
  STRIDE_FIELD(Eigen::Vector3d, damping, "N*s/m", Range{0, 1e4}){20, 20, 15};       // B, N s/m
  STRIDE_FIELD(double, rot_stiffness, "N*m/rad", Range{0, 1e4}) = 20;               // N m/rad
  // N m s/rad
  STRIDE_FIELD(double, rot_damping, "N*m*s/rad", Range{0, 1e3}) = 0.3;
  STRIDE_FIELD(double, hold_stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "LandingImpedanceParameters";
};

void register_landing_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
