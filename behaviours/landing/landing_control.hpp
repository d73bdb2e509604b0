#pragma once
// Landing impact control through joint positions (thesis Ch. 6 on a robot that takes positions,
// its Sec. 8.2 future work): around each touch-down the landing sole's height and the ankle's
// pitch and roll follow an admittance (Eq. 6.13, or Eq. 6.17 without mass) driven by the FSRs, then
// are handed back to the walking pattern.
//   LandingControl   PostureCorrectedRequest, ArmSwingRequest, WalkingJointRequest, FsrSensorData,
//                    FrameInfo -> JointRequest, LandingControlState
// It takes WalkingJointRequestAssembler's place (`mr JointRequest LandingControl`); a scene that
// does not choose it walks exactly as before.
#include <array>

#include <Eigen/Core>

#include "behaviours/landing/admittance.hpp"
#include "behaviours/landing/landing_window.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"
#include "robot/model/kinematics/nao_chains.hpp"

namespace stride {

// What landing control did this frame, per foot (left, right).
struct LandingControlState {
  STRIDE_FIELDS(LandingControlState);
  STRIDE_FIELD((std::array<behaviours::LandingStage, 2>), stage){};
  // m, sole raised along the torso z axis
  STRIDE_FIELD(Eigen::Vector2d, lift, "m") = Eigen::Vector2d::Zero();
  // rad, added to AnklePitch
  STRIDE_FIELD(Eigen::Vector2d, pitch, "rad") = Eigen::Vector2d::Zero();
  STRIDE_FIELD(Eigen::Vector2d, roll, "rad") = Eigen::Vector2d::Zero();  // rad, added to AnkleRoll
  // N, FSR total less the robot's weight
  STRIDE_FIELD(double, excess_force, "N") = 0;

  static constexpr std::string_view kTypeName = "LandingControlState";
};

}  // namespace stride

namespace stride::behaviours {

// Defaults: a sole critically damped at 18 Hz that yields 1 mm per 20 N of impact beyond the
// robot's weight (a softer 3000 N/m sole lifted off again after most touch-downs at ODE's study
// setting: scenes/experiments/README.md); ankles that give 1 deg per 0.9 N m of moment.
struct LandingControlParameters {
  STRIDE_FIELDS(LandingControlParameters);
  // M of Eq. 6.13, kg (0: the first-order law of Eq. 6.17)
  STRIDE_FIELD(double, mass, "kg", Range{0, 100}) = 1.5;
  STRIDE_FIELD(double, damping, "N*s/m", Range{0, 1e5}) = 350;             // B, N s/m
  STRIDE_FIELD(double, stiffness, "N/m", Range{1, 1e6}) = 20000;           // K, N/m
  STRIDE_FIELD(double, ankle_inertia, "kg*m^2", Range{0, 10}) = 0.01;      // rotational M, kg m^2
  STRIDE_FIELD(double, ankle_damping, "N*m*s/rad", Range{0, 1e3}) = 1.4;   // N m s/rad
  STRIDE_FIELD(double, ankle_stiffness, "N*m/rad", Range{0.1, 1e5}) = 50;  // N m/rad
  // N the FSRs read with the robot at rest (5.305 kg)
  STRIDE_FIELD(double, weight, "N", Range{0, 1000}) = 52.04;
  STRIDE_FIELD(double, max_lift, "m", Range{0, 0.05}) = 0.02;   // m, largest raise of a sole
  STRIDE_FIELD(double, max_drop, "m", Range{0, 0.05}) = 0.01;   // m, largest lowering of a sole
  STRIDE_FIELD(double, max_tilt, "rad", Range{0, 0.5}) = 0.15;  // rad, largest ankle offset
  // m, ankle frame: no moment here
  STRIDE_FIELD(Eigen::Vector2d, cop_reference, "m", Range{-0.1, 0.1}) = Eigen::Vector2d::Zero();
  // servo stiffness of the landing leg while it acts
  STRIDE_FIELD(double, landing_stiffness, "", Range{0, 1}) = 1;
  STRIDE_FIELD(double, lift_height, "m", Range{0, 0.1}) = 0.004;  // see LandingWindow
  STRIDE_FIELD(double, touch_height, "m", Range{0, 0.1}) = 0.0005;
  STRIDE_FIELD(double, contact_force, "N", Range{0, 200}) = 5;
  STRIDE_FIELD(double, hold_time, "s", Range{0, 2}) = 0.12;
  STRIDE_FIELD(double, return_time, "s", Range{0, 2}) = 0.10;

  Admittance sole() const { return {mass, damping, stiffness}; }
  Admittance ankle() const { return {ankle_inertia, ankle_damping, ankle_stiffness}; }
  LandingWindow window() const {
    return {lift_height, touch_height, contact_force, hold_time, return_time};
  }

  static constexpr std::string_view kTypeName = "LandingControlParameters";
};

// The leg's angles with its sole raised by `lift` along the torso's z axis (orientation kept,
// HipYawPitch kept: one motor drives both legs), then `pitch` and `roll` added at the ankle.
model::LegAngles offset_sole(model::Side side, const model::LegAngles& q, double lift, double pitch,
                             double roll);

// Moments about the ankle's pitch (y) and roll (x) axes of a vertical load at `cop` (ankle frame),
// measured from `reference`: the sole turns with them, as a joint axis along the moment.
Eigen::Vector2d sole_moments(double load, const Eigen::Vector2d& cop,
                             const Eigen::Vector2d& reference);

void register_landing_control(ModuleRegistry& registry);

}  // namespace stride::behaviours
