#pragma once
// Analytic inverse kinematics of the NAO legs: sole pose in the torso frame -> six joint angles.
// Angles in the robot's sign convention, order HipYawPitch, HipRoll, HipPitch, Knee, AnklePitch,
// AnkleRoll (as nao_fk.hpp). Knee >= 0 (the NAO's knee bends one way). Allocation-free.
#include <cstdint>

#include <Eigen/Geometry>

#include "robot/model/kinematics/nao_chains.hpp"

namespace stride::model {

struct LegIkResult {
  LegAngles q{};
  // Geometric only: the ankle target lies within the leg's reach (limits are beyond_limits').
  bool reachable = true;      // false: the ankle target was moved onto the reachable shell
  bool knee_clamped = false;  // the target was beyond the stretched leg (knee set to 0)
  double position_error = 0;  // distance the ankle target had to move (m)
  double orientation_error =
      0;  // rotation (rad) between the reached and the wanted foot; only
          // non-zero when HipYawPitch was imposed (leg_ik_with_hip_yaw_pitch)
  // Joints whose angle lies outside the NAO's limits (nao/joint_limits.hpp): bit i for q[i].
  // The angles are left as solved: clamping them is the command guard's job, and saying so here
  // lets a walking module count the frames it asked for more than the robot can do.
  std::uint8_t beyond_limits = 0;
  bool within_limits() const { return beyond_limits == 0; }
};

// Bit i set for each angle of a leg (chain order) outside the NAO's joint limits.
std::uint8_t leg_limit_violations(Side side, const LegAngles& q);

// Full 6-DoF solution: reaches any pose within the leg's workspace exactly.
LegIkResult leg_ik(Side side, const Eigen::Isometry3d& sole_in_torso);

// HipYawPitch imposed (one motor drives both legs): the ankle position is reached exactly, the
// foot orientation as closely as the remaining ankle pitch/roll allow.
LegIkResult leg_ik_with_hip_yaw_pitch(Side side, const Eigen::Isometry3d& sole_in_torso,
                                      double hip_yaw_pitch);

struct LegsIkResult {
  LegIkResult left, right;
};

// Both legs with the shared HipYawPitch: the left leg is solved fully and its yaw-pitch is
// imposed on the right leg, as the robot's single motor follows the left joint's command.
// Targets that agree on HipYawPitch are both reached exactly.
LegsIkResult legs_ik(const Eigen::Isometry3d& left_sole, const Eigen::Isometry3d& right_sole);

// Flat soles under an upright torso, each at a position (torso frame) and turned by a yaw about
// the torso's z axis. The left leg is solved fully and the right one with its HipYawPitch
// (legs_ik): opposite yaws of mirrored positions are both reached exactly, other pairs leave the
// right foot's yaw off by its orientation_error (HipYawPitch depends on the foot's position too).
LegsIkResult legs_ik_upright(const Eigen::Vector3d& left_sole, double left_yaw,
                             const Eigen::Vector3d& right_sole, double right_yaw);

struct TurnedLegsIkResult {
  LegsIkResult legs;
  double torso_yaw = 0.0;  // the upright torso's yaw at which both soles are reached
  double yaw_error = 0.0;  // the right foot's yaw left over (rad), 0 when solved
};

// Flat soles given relative to the torso origin in axes turned with the world's (upright, yaw 0)
// and by their yaws there: the one torso yaw at which the shared HipYawPitch reaches both
// exactly, found by the secant method from the mean of the two yaws, and the angles there.
// A turning walk's torso is yawed so; a turn beyond the hip's reach keeps the best yaw found.
TurnedLegsIkResult legs_ik_turned(const Eigen::Vector3d& left_sole, double left_yaw,
                                  const Eigen::Vector3d& right_sole, double right_yaw);

// The mean of two yaws along the shorter arc, in (-pi, pi].
double torso_yaw_between(double left_yaw, double right_yaw);

}  // namespace stride::model
