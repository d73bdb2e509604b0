#pragma once
// Where the robot is, from what it measures: the torso's yaw from the gyro's z rate integrated,
// and its place by chaining the support foot (the more loaded one, by the FSRs) through the
// legs' forward kinematics from the joint encoders: while a foot supports, the torso is placed
// from it; when the other foot takes the load, that foot's place is fixed from the torso.
// Slip of a loaded foot on the floor is not seen in the place; its spin is seen in the yaw.
#include <Eigen/Core>

namespace stride::walking {

enum class OdometrySupport { none, left, right };

struct LegOdometryState {
  OdometrySupport support = OdometrySupport::none;
  Eigen::Vector2d foot = Eigen::Vector2d::Zero();   // the support foot's sole, world (x, y)
  Eigen::Vector2d torso = Eigen::Vector2d::Zero();  // torso origin, world (x, y)
  double yaw = 0.0;                                 // torso yaw, world
  long exchanges = 0;                               // support exchanges so far
};

// One frame: the torso's yaw now, each sole's position in the upright torso frame turned by
// nothing but that yaw (forward kinematics, x and y), and each foot's measured load (N).
// A foot takes over the support when it carries more than `exchange_share` of both feet's load.
LegOdometryState advance_leg_odometry(const LegOdometryState& s, double yaw,
                                      const Eigen::Vector2d& left_in_torso,
                                      const Eigen::Vector2d& right_in_torso, double left_load,
                                      double right_load, double exchange_share);

}  // namespace stride::walking
