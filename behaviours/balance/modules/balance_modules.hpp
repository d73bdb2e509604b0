#pragma once
// Standing balance strategies of thesis Ch. 7 as modules that provide the JointRequest (the
// standing posture plus corrections); choose one with `mr JointRequest <module>`:
//   AnkleBalance     PD on the CoM through the ankle ZMP (Eq. 7.16, Eq. 7.18)
//   HipBalance       bang-bang HAT torque profile (Algorithm 2), ankles hold the posture
//   CombinedBalance  ankle ZMP at the sole border + bang-bang hip (Eq. 7.36)
//   LqrBalance       LQR on [x, theta, xdot, thetadot] -> [x_zmp, tau_h] (Eq. 7.39)
// All require ComState, BalanceModel (ComStateEstimator), JointSensorData and FrameInfo.
// BalanceOutlook (balance_outlook.hpp) predicts which of them would recover the robot.
#include <Eigen/Core>

#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::behaviours {

// Defaults: kp, kd of the thesis' closed-loop example (Fig. 7.5).
struct AnkleBalanceParameters {
  double kp = 72;
  double kd = 12;
  double stiffness = 1;

  static constexpr std::string_view kTypeName = "AnkleBalanceParameters";
  static constexpr auto fields() {
    using P = AnkleBalanceParameters;
    return std::make_tuple(field("kp", &P::kp, "1/s^2", Range{0, 1e4}),
                           field("kd", &P::kd, "1/s", Range{0, 1e3}),
                           field("stiffness", &P::stiffness, "", Range{0, 1}));
  }
};

// Hip torques below the two hip pitch servos' joint-side stall torque (2 x 8.51 N m).
struct HipBalanceParameters {
  double tau_forward = 14;    // tau_{n-f}, N m
  double tau_backward = -14;  // tau_{n-b}, N m
  double trigger = 0.01;      // capture-point deviation that starts a profile, m
  double hold_time = 0.5;     // HAT kept at its peak after t2, s
  double return_time = 1.0;   // back to the posture afterwards, s
  bool keep_com = true;       // tilt back about the ankles by the trunk's CoM shift
  double stiffness = 1;

  static constexpr std::string_view kTypeName = "HipBalanceParameters";
  static constexpr auto fields() {
    using P = HipBalanceParameters;
    return std::make_tuple(field("tau_forward", &P::tau_forward, "N*m", Range{0, 100}),
                           field("tau_backward", &P::tau_backward, "N*m", Range{-100, 0}),
                           field("trigger", &P::trigger, "m", Range{0, 1}),
                           field("hold_time", &P::hold_time, "s", Range{0, 10}),
                           field("return_time", &P::return_time, "s", Range{0.01, 10}),
                           field("keep_com", &P::keep_com),
                           field("stiffness", &P::stiffness, "", Range{0, 1}));
  }
};

struct CombinedBalanceParameters {
  double kp = 72;
  double kd = 12;
  double tau_forward = 14;
  double tau_backward = -14;
  double margin = 0.005;  // sole edges less this are the ankle's ZMP range the hip plans with
  double hold_time = 0.5;
  double return_time = 1.0;
  double stiffness = 1;

  static constexpr std::string_view kTypeName = "CombinedBalanceParameters";
  static constexpr auto fields() {
    using P = CombinedBalanceParameters;
    return std::make_tuple(field("kp", &P::kp, "1/s^2", Range{0, 1e4}),
                           field("kd", &P::kd, "1/s", Range{0, 1e3}),
                           field("tau_forward", &P::tau_forward, "N*m", Range{0, 100}),
                           field("tau_backward", &P::tau_backward, "N*m", Range{-100, 0}),
                           field("margin", &P::margin, "m", Range{0, 0.1}),
                           field("hold_time", &P::hold_time, "s", Range{0, 10}),
                           field("return_time", &P::return_time, "s", Range{0.01, 10}),
                           field("stiffness", &P::stiffness, "", Range{0, 1}));
  }
};

// Defaults: the weights printed with Figs. 7.13-7.14.
struct LqrBalanceParameters {
  Eigen::Vector4d q_diagonal{2000, 500, 1, 10};  // [x, theta, xdot, thetadot]
  Eigen::Vector2d r_diagonal{4500000, 100};      // [x_zmp, tau_h]
  double tau_max = 14;                           // |tau_h| limit, N m
  double stiffness = 1;

  static constexpr std::string_view kTypeName = "LqrBalanceParameters";
  static constexpr auto fields() {
    using P = LqrBalanceParameters;
    return std::make_tuple(field("q_diagonal", &P::q_diagonal, "", Range{0, 1e12}),
                           field("r_diagonal", &P::r_diagonal, "", Range{1e-9, 1e12}),
                           field("tau_max", &P::tau_max, "N*m", Range{0, 100}),
                           field("stiffness", &P::stiffness, "", Range{0, 1}));
  }
};

// ComStateEstimator and the four strategies.
void register_balance_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
