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
  STRIDE_FIELDS(AnkleBalanceParameters);
  STRIDE_FIELD(double, kp, "1/s^2", Range{0, 1e4}) = 72;
  STRIDE_FIELD(double, kd, "1/s", Range{0, 1e3}) = 12;
  STRIDE_FIELD(double, stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "AnkleBalanceParameters";
};

// Hip torques below the two hip pitch servos' joint-side stall torque (2 x 8.51 N m).
struct HipBalanceParameters {
  STRIDE_FIELDS(HipBalanceParameters);
  STRIDE_FIELD(double, tau_forward, "N*m", Range{0, 100}) = 14;     // tau_{n-f}, N m
  STRIDE_FIELD(double, tau_backward, "N*m", Range{-100, 0}) = -14;  // tau_{n-b}, N m
  // capture-point deviation that starts a profile, m
  STRIDE_FIELD(double, trigger, "m", Range{0, 1}) = 0.01;
  STRIDE_FIELD(double, hold_time, "s", Range{0, 10}) = 0.5;  // HAT kept at its peak after t2, s
  // back to the posture afterwards, s
  STRIDE_FIELD(double, return_time, "s", Range{0.01, 10}) = 1.0;
  STRIDE_FIELD(bool, keep_com) = true;  // tilt back about the ankles by the trunk's CoM shift
  STRIDE_FIELD(double, stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "HipBalanceParameters";
};

struct CombinedBalanceParameters {
  STRIDE_FIELDS(CombinedBalanceParameters);
  STRIDE_FIELD(double, kp, "1/s^2", Range{0, 1e4}) = 72;
  STRIDE_FIELD(double, kd, "1/s", Range{0, 1e3}) = 12;
  STRIDE_FIELD(double, tau_forward, "N*m", Range{0, 100}) = 14;
  STRIDE_FIELD(double, tau_backward, "N*m", Range{-100, 0}) = -14;
  // sole edges less this are the ankle's ZMP range the hip plans with
  STRIDE_FIELD(double, margin, "m", Range{0, 0.1}) = 0.005;
  STRIDE_FIELD(double, hold_time, "s", Range{0, 10}) = 0.5;
  STRIDE_FIELD(double, return_time, "s", Range{0.01, 10}) = 1.0;
  STRIDE_FIELD(double, stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "CombinedBalanceParameters";
};

// Defaults: the weights printed with Figs. 7.13-7.14.
struct LqrBalanceParameters {
  STRIDE_FIELDS(LqrBalanceParameters);
  // [x, theta, xdot, thetadot]
  STRIDE_FIELD(Eigen::Vector4d, q_diagonal, "", Range{0, 1e12}){2000, 500, 1, 10};
  // [x_zmp, tau_h]
  STRIDE_FIELD(Eigen::Vector2d, r_diagonal, "", Range{1e-9, 1e12}){4500000, 100};
  // |tau_h| limit, N m
  STRIDE_FIELD(double, tau_max, "N*m", Range{0, 100}) = 14;
  STRIDE_FIELD(double, stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "LqrBalanceParameters";
};

// ComStateEstimator and the four strategies.
void register_balance_modules(ModuleRegistry& registry);

}  // namespace stride::behaviours
