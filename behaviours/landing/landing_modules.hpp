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
  double speed = 0.2;     // m/s
  double descent = 0.03;  // m below its starting height where the plan ends
  double hold_stiffness = 1;

  static constexpr std::string_view kTypeName = "LandingPositionParameters";
  static constexpr auto fields() {
    using P = LandingPositionParameters;
    return std::make_tuple(field("speed", &P::speed, "m/s", Range{1e-3, 2}),
                           field("descent", &P::descent, "m", Range{0, 0.2}),
                           field("hold_stiffness", &P::hold_stiffness, "", Range{0, 1}));
  }
};

// The same plan, and the gains of Eq. 6.17 (translation in the torso frame's axes).
struct LandingImpedanceParameters {
  double speed = 0.2;
  double descent = 0.03;
  Eigen::Vector3d stiffness{2000, 2000, 300};  // K, N/m
  Eigen::Vector3d damping{20, 20, 15};         // B, N s/m
  double rot_stiffness = 20;                   // N m/rad
  double rot_damping = 0.3;                    // N m s/rad
  double hold_stiffness = 1;

  static constexpr std::string_view kTypeName = "LandingImpedanceParameters";
  static constexpr auto fields() {
    using P = LandingImpedanceParameters;
    return std::make_tuple(field("speed", &P::speed, "m/s", Range{1e-3, 2}),
                           field("descent", &P::descent, "m", Range{0, 0.2}),
                           field("stiffness", &P::stiffness, "N/m", Range{0, 1e6}),
                           field("damping", &P::damping, "N*s/m", Range{0, 1e4}),
                           field("rot_stiffness", &P::rot_stiffness, "N*m/rad", Range{0, 1e4}),
                           field("rot_damping", &P::rot_damping, "N*m*s/rad", Range{0, 1e3}),
                           field("hold_stiffness", &P::hold_stiffness, "", Range{0, 1}));
  }
};

void register_landing_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
