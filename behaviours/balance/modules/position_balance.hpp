#pragma once
// Standing balance through joint positions and stiffness only (thesis Ch. 7 on a robot that takes
// no torques, its Sec. 8.2 future work):
//   PositionBalance  ComState, BalanceModel, JointSensorData, FrameInfo -> JointRequest
// Ankle strategy: the CoP is regulated through the ankle pitch positions: the Ch. 7 PD on the CoM
// (Eq. 7.16, Eq. 7.18, Eq. 7.19) demands a ZMP, the FSR CoP is measured, and their difference as an
// ankle torque (Eq. 7.10) drives an ankle admittance whose offset is added to the posture. Hip
// strategy: the bang-bang HAT excursion (Eq. 7.24, Eq. 7.27) sent to the hip pitch positions.
// Combined: both, the ankle aiming at the sole border (Eq. 7.36).
// With `strategy` auto, each disturbance is classified by the Ch. 7 boundaries (least effort
// first: ankle, hip, combined) and met with the strategy chosen.
#include <array>
#include <string_view>

#include "behaviours/balance/strategy_classifier.hpp"
#include "robot/framework/module_registry.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::behaviours {

enum class BalanceChoice { automatic, ankle, hip, combined };

}  // namespace stride::behaviours

namespace stride {
template <>
struct EnumNames<behaviours::BalanceChoice> {
  static constexpr std::string_view type_name = "BalanceChoice";
  static constexpr std::array<std::string_view, 4> names{"auto", "ankle", "hip", "combined"};
};

// What PositionBalance is doing: the strategy the Ch. 7 boundaries predicted for the last
// disturbance, the one running, and the joint offsets it sends.
struct PositionBalanceState {
  STRIDE_FIELDS(PositionBalanceState);
  STRIDE_FIELD(balance::Strategy, predicted) = balance::Strategy::ankle;
  STRIDE_FIELD(balance::Strategy, strategy) = balance::Strategy::ankle;
  STRIDE_FIELD(double, capture_point, "m") = 0;  // m, x + xdot / omega when the strategy was chosen
  STRIDE_FIELD(double, demanded_zmp, "m") = 0;   // m, of Eq. 7.18 clipped by Eq. 7.19
  STRIDE_FIELD(double, ankle_offset, "rad") = 0;  // rad, added to both AnklePitch joints
  // rad, trunk forward of the posture (both HipPitch at posture - it)
  STRIDE_FIELD(double, hat_angle, "rad") = 0;

  static constexpr std::string_view kTypeName = "PositionBalanceState";
};
}  // namespace stride

namespace stride::behaviours {

// Defaults: the PD of Fig. 7.5 and the hip torques of HipBalance; the ankle admittance turns a
// 1 N m CoP error into 0.02 rad/s of ankle motion and lets go of an offset in 0.25 s (50 times
// the first gain rocked the standing robot heel to toe with its CoP at the sole's edges).
struct PositionBalanceParameters {
  STRIDE_FIELDS(PositionBalanceParameters);
  STRIDE_FIELD(BalanceChoice, strategy) = BalanceChoice::automatic;
  STRIDE_FIELD(double, kp, "1/s^2", Range{0, 1e4}) = 72;  // 1/s^2, Eq. 7.16
  STRIDE_FIELD(double, kd, "1/s", Range{0, 1e3}) = 12;
  // N m s/rad: CoP-error torque per ankle speed
  STRIDE_FIELD(double, ankle_damping, "N*m*s/rad", Range{0.01, 1e3}) = 50;
  // N m/rad: pulls the offset back to the posture
  STRIDE_FIELD(double, ankle_stiffness, "N*m/rad", Range{0.01, 1e4}) = 200;
  STRIDE_FIELD(double, max_ankle_offset, "rad", Range{0, 0.5}) = 0.25;
  // m: the sole less this is the ZMP the ankle aims for
  STRIDE_FIELD(double, margin, "m", Range{0, 0.05}) = 0.01;
  STRIDE_FIELD(double, tau_forward, "N*m", Range{0.01, 100}) = 14;
  STRIDE_FIELD(double, tau_backward, "N*m", Range{-100, -0.01}) = -14;
  // m: capture-point deviation that starts a HAT excursion
  STRIDE_FIELD(double, trigger, "m", Range{0, 1}) = 0.01;
  STRIDE_FIELD(double, hold_time, "s", Range{0, 10}) = 0.5;
  STRIDE_FIELD(double, return_time, "s", Range{0.01, 10}) = 1.0;
  STRIDE_FIELD(bool, keep_com) = true;
  STRIDE_FIELD(double, stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "PositionBalanceParameters";
};

// The ankle torque (N m, Eq. 7.10) that would move the CoP from `cop` to `zmp` (m) under `mass`.
inline double cop_torque_error(double mass, double g, double zmp, double cop) {
  return mass * g * (zmp - cop);
}

// The strategy that meets a disturbance: the one `choice` forces, or (auto) the least effort the
// Ch. 7 boundaries `predicted`; past every boundary the combined strategy, as best effort.
balance::Strategy chosen_strategy(BalanceChoice choice, balance::Strategy predicted);

void register_position_balance(ModuleRegistry& registry);

}  // namespace stride::behaviours
