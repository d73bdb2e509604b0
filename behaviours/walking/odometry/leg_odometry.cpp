#include "behaviours/walking/odometry/leg_odometry.hpp"

#include "behaviours/walking/steps/pose2.hpp"

namespace stride::walking {

namespace {
Eigen::Vector2d in_world(double yaw, const Eigen::Vector2d& v) {
  return rotated(yaw, v.x(), v.y());
}
}  // namespace

LegOdometryState advance_leg_odometry(const LegOdometryState& s, double yaw,
                                      const Eigen::Vector2d& left_in_torso,
                                      const Eigen::Vector2d& right_in_torso, double left_load,
                                      double right_load, double exchange_share) {
  LegOdometryState n = s;
  n.yaw = yaw;
  const double total = left_load + right_load;
  OdometrySupport loaded = n.support;
  if (total > 0.0) {
    if (left_load > exchange_share * total) loaded = OdometrySupport::left;
    if (right_load > exchange_share * total) loaded = OdometrySupport::right;
  }
  const auto sole = [&](OdometrySupport f) {
    return f == OdometrySupport::left ? left_in_torso : right_in_torso;
  };
  if (n.support == OdometrySupport::none) {
    // The first support foot is placed from the torso where the odometry starts (the origin).
    if (loaded == OdometrySupport::none) return n;
    n.support = loaded;
    n.foot = n.torso + in_world(yaw, sole(loaded));
    return n;
  }
  // The torso from the foot that supported until now, then the exchange if the other took over.
  n.torso = n.foot - in_world(yaw, sole(n.support));
  if (loaded != n.support) {
    n.support = loaded;
    n.foot = n.torso + in_world(yaw, sole(loaded));
    ++n.exchanges;
  }
  return n;
}

}  // namespace stride::walking
