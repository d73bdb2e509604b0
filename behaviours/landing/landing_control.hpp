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
  std::array<behaviours::LandingStage, 2> stage{};
  Eigen::Vector2d lift = Eigen::Vector2d::Zero();   // m, sole raised along the torso z axis
  Eigen::Vector2d pitch = Eigen::Vector2d::Zero();  // rad, added to AnklePitch
  Eigen::Vector2d roll = Eigen::Vector2d::Zero();   // rad, added to AnkleRoll
  double excess_force = 0;                          // N, FSR total less the robot's weight

  static constexpr std::string_view kTypeName = "LandingControlState";
  static constexpr auto fields() {
    using L = LandingControlState;
    return std::make_tuple(field("stage", &L::stage), field("lift", &L::lift, "m"),
                           field("pitch", &L::pitch, "rad"), field("roll", &L::roll, "rad"),
                           field("excess_force", &L::excess_force, "N"));
  }
};

}  // namespace stride

namespace stride::behaviours {

// Defaults: a sole critically damped at 18 Hz that yields 1 mm per 20 N of impact beyond the
// robot's weight (a softer 3000 N/m sole lifted off again after most touch-downs at ODE's study
// setting: scenes/experiments/README.md); ankles that give 1 deg per 0.9 N m of moment.
struct LandingControlParameters {
  double mass = 1.5;            // M of Eq. 6.13, kg (0: the first-order law of Eq. 6.17)
  double damping = 350;         // B, N s/m
  double stiffness = 20000;     // K, N/m
  double ankle_inertia = 0.01;  // rotational M, kg m^2
  double ankle_damping = 1.4;   // N m s/rad
  double ankle_stiffness = 50;  // N m/rad
  double weight = 52.04;        // N the FSRs read with the robot at rest (5.305 kg)
  double max_lift = 0.02;       // m, largest raise of a sole
  double max_drop = 0.01;       // m, largest lowering of a sole
  double max_tilt = 0.15;       // rad, largest ankle offset
  Eigen::Vector2d cop_reference = Eigen::Vector2d::Zero();  // m, ankle frame: no moment here
  double landing_stiffness = 1;  // servo stiffness of the landing leg while it acts
  double lift_height = 0.004;    // see LandingWindow
  double touch_height = 0.0005;
  double contact_force = 5;
  double hold_time = 0.12;
  double return_time = 0.10;

  Admittance sole() const { return {mass, damping, stiffness}; }
  Admittance ankle() const { return {ankle_inertia, ankle_damping, ankle_stiffness}; }
  LandingWindow window() const {
    return {lift_height, touch_height, contact_force, hold_time, return_time};
  }

  static constexpr std::string_view kTypeName = "LandingControlParameters";
  static constexpr auto fields() {
    using P = LandingControlParameters;
    return std::make_tuple(
        field("mass", &P::mass, "kg", Range{0, 100}),
        field("damping", &P::damping, "N*s/m", Range{0, 1e5}),
        field("stiffness", &P::stiffness, "N/m", Range{1, 1e6}),
        field("ankle_inertia", &P::ankle_inertia, "kg*m^2", Range{0, 10}),
        field("ankle_damping", &P::ankle_damping, "N*m*s/rad", Range{0, 1e3}),
        field("ankle_stiffness", &P::ankle_stiffness, "N*m/rad", Range{0.1, 1e5}),
        field("weight", &P::weight, "N", Range{0, 1000}),
        field("max_lift", &P::max_lift, "m", Range{0, 0.05}),
        field("max_drop", &P::max_drop, "m", Range{0, 0.05}),
        field("max_tilt", &P::max_tilt, "rad", Range{0, 0.5}),
        field("cop_reference", &P::cop_reference, "m", Range{-0.1, 0.1}),
        field("landing_stiffness", &P::landing_stiffness, "", Range{0, 1}),
        field("lift_height", &P::lift_height, "m", Range{0, 0.1}),
        field("touch_height", &P::touch_height, "m", Range{0, 0.1}),
        field("contact_force", &P::contact_force, "N", Range{0, 200}),
        field("hold_time", &P::hold_time, "s", Range{0, 2}),
        field("return_time", &P::return_time, "s", Range{0, 2}));
  }
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
