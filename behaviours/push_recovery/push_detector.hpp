#pragma once
// The push detector of the walk: the CoM's deviation from the walking plan, held against the
// Ch. 7 boundaries, names the least-effort response, and past them the stepping response's new
// footstep (the capture point, which Ch. 7 names as the last resort but does not model).
#include <array>
#include <string_view>

#include <Eigen/Core>

#include "behaviours/balance/balance_params.hpp"
#include "robot/framework/reflect.hpp"

namespace stride::behaviours {

enum class PushResponse { none, ankle, hip, combined, step };

}  // namespace stride::behaviours

namespace stride {
template <>
struct EnumNames<behaviours::PushResponse> {
  static constexpr std::string_view type_name = "PushResponse";
  static constexpr std::array<std::string_view, 5> names{"none", "ankle", "hip", "combined",
                                                         "step"};
};
}  // namespace stride

namespace stride::behaviours {

// The capture point's deviation from the plan's, x + xdot / omega per axis with omega^2 = g / z
// (Eq. 7.1), from the CoM's deviation `dev` (m) and its rate (m/s) at CoM height `z`.
Eigen::Vector2d capture_deviation(const Eigen::Vector2d& dev, const Eigen::Vector2d& rate, double g,
                                  double z);

// The Ch. 7 model of a deviation from the plan along one axis: the ankle has left what the sole
// offers beyond the planned ZMP (both measured from the stance ankle).
balance::BalanceParams deviation_model(balance::BalanceParams robot, double sole_back,
                                       double sole_front, double planned_zmp);

// The response a deviation (x - x_plan, xdot - xdot_plan) needs: none while its capture point
// stays within `threshold` (the walk's own noise), else the least effort of the ankle (Eq. 7.13),
// the hip (Eq. 7.30) and both (Eq. 7.37) when `hip` is allowed, else a step.
PushResponse classify_deviation(const balance::BalanceParams& p, const balance::ComState& deviation,
                                double threshold, bool hip);

// The stance ankle's response through positions: per axis the capture-point deviation beyond its
// dead band (the walk's own deviation) times the gain, clamped to +-max_angle; pitch leans on the
// toes for a deviation forward, roll on the sole's +y edge for one to the left (the CoP moved
// toward the capture point, the ankle strategy of Sec. 7.3). Returns (pitch, roll) offsets, rad.
Eigen::Vector2d ankle_response(const Eigen::Vector2d& capture_deviation,
                               const Eigen::Vector2d& dead_band, const Eigen::Vector2d& gain,
                               double max_angle);

// How far a landing may move from the plan: forward/backward, and sideways away from the stance
// foot (outward) or towards it (inward).
struct StepLimits {
  double forward = 0.04, backward = 0.03, outward = 0.04, inward = 0.01;
};

// The stepping response: the landing of the swing foot (left when `left_swings`) moved by the
// capture-point deviation times `gain`, within the limits (y > 0 is the left foot's outward).
Eigen::Vector2d capture_step(const Eigen::Vector2d& capture_deviation, double gain,
                             const StepLimits& limits, bool left_swings);

}  // namespace stride::behaviours
