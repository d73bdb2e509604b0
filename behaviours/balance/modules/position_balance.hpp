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
  balance::Strategy predicted = balance::Strategy::ankle;
  balance::Strategy strategy = balance::Strategy::ankle;
  double capture_point = 0;  // m, x + xdot / omega when the strategy was chosen
  double demanded_zmp = 0;   // m, of Eq. 7.18 clipped by Eq. 7.19
  double ankle_offset = 0;   // rad, added to both AnklePitch joints
  double hat_angle = 0;      // rad, trunk forward of the posture (both HipPitch at posture - it)

  static constexpr std::string_view kTypeName = "PositionBalanceState";
  static constexpr auto fields() {
    using S = PositionBalanceState;
    return std::make_tuple(field("predicted", &S::predicted), field("strategy", &S::strategy),
                           field("capture_point", &S::capture_point, "m"),
                           field("demanded_zmp", &S::demanded_zmp, "m"),
                           field("ankle_offset", &S::ankle_offset, "rad"),
                           field("hat_angle", &S::hat_angle, "rad"));
  }
};
}  // namespace stride

namespace stride::behaviours {

// Defaults: the PD of Fig. 7.5 and the hip torques of HipBalance; the ankle admittance turns a
// 1 N m CoP error into 0.02 rad/s of ankle motion and lets go of an offset in 0.25 s (50 times
// the first gain rocked the standing robot heel to toe with its CoP at the sole's edges).
struct PositionBalanceParameters {
  BalanceChoice strategy = BalanceChoice::automatic;
  double kp = 72;                // 1/s^2, Eq. 7.16
  double kd = 12;                // 1/s
  double ankle_damping = 50;     // N m s/rad: CoP-error torque per ankle speed
  double ankle_stiffness = 200;  // N m/rad: pulls the offset back to the posture
  double max_ankle_offset = 0.25;
  double margin = 0.01;  // m: the sole less this is the ZMP the ankle aims for
  double tau_forward = 14;
  double tau_backward = -14;
  double trigger = 0.01;  // m: capture-point deviation that starts a HAT excursion
  double hold_time = 0.5;
  double return_time = 1.0;
  bool keep_com = true;
  double stiffness = 1;

  static constexpr std::string_view kTypeName = "PositionBalanceParameters";
  static constexpr auto fields() {
    using P = PositionBalanceParameters;
    return std::make_tuple(
        field("strategy", &P::strategy), field("kp", &P::kp, "1/s^2", Range{0, 1e4}),
        field("kd", &P::kd, "1/s", Range{0, 1e3}),
        field("ankle_damping", &P::ankle_damping, "N*m*s/rad", Range{0.01, 1e3}),
        field("ankle_stiffness", &P::ankle_stiffness, "N*m/rad", Range{0.01, 1e4}),
        field("max_ankle_offset", &P::max_ankle_offset, "rad", Range{0, 0.5}),
        field("margin", &P::margin, "m", Range{0, 0.05}),
        field("tau_forward", &P::tau_forward, "N*m", Range{0.01, 100}),
        field("tau_backward", &P::tau_backward, "N*m", Range{-100, -0.01}),
        field("trigger", &P::trigger, "m", Range{0, 1}),
        field("hold_time", &P::hold_time, "s", Range{0, 10}),
        field("return_time", &P::return_time, "s", Range{0.01, 10}),
        field("keep_com", &P::keep_com), field("stiffness", &P::stiffness, "", Range{0, 1}));
  }
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
