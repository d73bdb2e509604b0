#pragma once
// Leg joint angles of a pattern sample (Sec. 3.6, Fig. 3.13): the feet relative to the waist,
// p_f - p_w, with the torso upright and the soles flat, through the analytic leg IK.
#include <array>
#include <cstdint>
#include <string_view>

#include <Eigen/Core>

#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "robot/model/kinematics/nao_chains.hpp"

namespace stride::walking {

struct LegJoints {
  model::LegAngles left{};  // HipYawPitch, HipRoll, HipPitch, KneePitch, AnklePitch, AnkleRoll
  model::LegAngles right{};
  bool reachable = true;  // false: a foot was out of the leg's reach and the IK clamped it
  // Angles outside the NAO's joint limits: bit i for column i of kLegJointNames (left 0-5, right
  // 6-11). The command guard will clamp them; the pattern asked for more than the robot can do.
  std::uint16_t beyond_limits = 0;
};

// The twelve columns in the order of LegJoints (left leg, then right leg).
inline constexpr std::array<std::string_view, 12> kLegJointNames = {
    "LHipYawPitch", "LHipRoll", "LHipPitch", "LKneePitch", "LAnklePitch", "LAnkleRoll",
    "RHipYawPitch", "RHipRoll", "RHipPitch", "RKneePitch", "RAnklePitch", "RAnkleRoll"};

LegJoints leg_joints(const PatternSample& s);

// Hip, knee and ankle of one leg in the world frame, for the stick diagram (Fig. 3.18).
struct LegPoints {
  Eigen::Vector3d hip, knee, ankle;
};
LegPoints leg_points(model::Side side, const model::LegAngles& q, const Eigen::Vector3d& waist);

}  // namespace stride::walking
