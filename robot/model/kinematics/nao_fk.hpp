#pragma once
// Analytic forward kinematics of the NAO chains from the D-H tables of thesis App. B.
// Angles are in the robot's (LoLA) sign convention and chain order (see nao_chains.hpp); the
// sign flips of Table B.8 are applied inside. End effectors, all with axes parallel to the torso
// at q = 0 (like the URDF link frames):
//   head: the HeadPitch frame; arms: the hand point HandOffsetX ahead of the wrist;
//   legs: the sole point FootHeight below the ankle (the foot coordinate system, FCS).
#include <span>

#include <Eigen/Geometry>

#include "robot/model/kinematics/nao_chains.hpp"

namespace stride::model {

// End effector in the torso frame (RCS). q.size() must equal chain_joints(chain).size().
Eigen::Isometry3d chain_fk(NaoChain chain, std::span<const double> q);

// Leg end effector (sole frame) in the torso frame (Tables B.4, B.5).
Eigen::Isometry3d leg_fk(Side side, const LegAngles& q);

// Hand point in the torso frame (Table B.2); q = ShoulderPitch .. WristYaw.
Eigen::Isometry3d arm_fk(Side side, std::span<const double> q);

// Torso frame in the sole frame (FCS, Tables B.6, B.7): the same chain walked from the foot up.
Eigen::Isometry3d torso_in_foot_fk(Side side, const LegAngles& q);

// Every intermediate D-H frame of a leg in the torso frame (frames[i] is the frame of joint i,
// its z axis that joint's axis in D-H sign) plus the sole frame in frames[6]: used by Jacobians.
void leg_dh_frames(Side side, const LegAngles& q, std::array<Eigen::Isometry3d, 7>& frames);

// Sign with which the robot's angle enters the D-H table in the RCS (Table B.8).
double leg_dh_sign(Side side, int joint);

}  // namespace stride::model
