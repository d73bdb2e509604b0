#include "behaviours/push_recovery/push_detector.hpp"

#include <algorithm>
#include <cmath>

#include "behaviours/balance/strategy_classifier.hpp"

namespace stride::behaviours {

Eigen::Vector2d capture_deviation(const Eigen::Vector2d& dev, const Eigen::Vector2d& rate, double g,
                                  double z) {
  return dev + rate / std::sqrt(g / z);  // Eq. 7.13's left side, per axis
}

balance::BalanceParams deviation_model(balance::BalanceParams robot, double sole_back,
                                       double sole_front, double planned_zmp) {
  robot.zmp_min = sole_back - planned_zmp;
  robot.zmp_max = sole_front - planned_zmp;
  return robot;
}

PushResponse classify_deviation(const balance::BalanceParams& p, const balance::ComState& deviation,
                                double threshold, bool hip) {
  const double xi = balance::capture_point(deviation, p.omega());
  if (std::abs(xi) < threshold) return PushResponse::none;
  if (!(p.zmp_min < p.zmp_max)) return PushResponse::step;  // the planned ZMP left the sole
  if (!hip) return xi >= p.zmp_min && xi <= p.zmp_max ? PushResponse::ankle : PushResponse::step;
  switch (balance::classify(p, deviation).strategy) {
    case balance::Strategy::ankle:
      return PushResponse::ankle;
    case balance::Strategy::hip:
      return PushResponse::hip;
    case balance::Strategy::combined:
      return PushResponse::combined;
    case balance::Strategy::none:
      break;
  }
  return PushResponse::step;
}

Eigen::Vector2d ankle_response(const Eigen::Vector2d& capture_deviation,
                               const Eigen::Vector2d& dead_band, const Eigen::Vector2d& gain,
                               double max_angle) {
  Eigen::Vector2d out;
  for (int i = 0; i < 2; ++i) {
    const double xi = capture_deviation[i];
    const double beyond = std::copysign(std::max(0.0, std::abs(xi) - dead_band[i]), xi);
    out[i] = std::clamp(gain[i] * beyond, -max_angle, max_angle);
  }
  out[1] = -out[1];  // a positive roll lifts the sole's +y edge
  return out;
}

Eigen::Vector2d capture_step(const Eigen::Vector2d& capture_deviation, double gain,
                             const StepLimits& limits, bool left_swings) {
  const Eigen::Vector2d want = gain * capture_deviation;
  // For the left foot +y is outward (away from the right foot); for the right foot it is inward.
  const double y_max = left_swings ? limits.outward : limits.inward;
  const double y_min = left_swings ? -limits.inward : -limits.outward;
  return {std::clamp(want.x(), -limits.backward, limits.forward),
          std::clamp(want.y(), y_min, y_max)};
}

}  // namespace stride::behaviours
