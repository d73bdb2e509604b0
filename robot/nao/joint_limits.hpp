#pragma once
// NAO joint position limits in LoLA order (nao-facts.md, URDF-V5; right roll joints mirrored).
#include <array>

#include "robot/hal/joint_id.hpp"

namespace stride::nao {

struct JointRange {
  double lower, upper;  // rad (hands: open fraction)
};

inline constexpr std::array<JointRange, hal::kNumJoints> kJointLimits = {{
    {-2.08567, 2.08567},     // HeadYaw
    {-0.671952, 0.514872},   // HeadPitch
    {-2.08567, 2.08567},     // LShoulderPitch
    {-0.314159, 1.32645},    // LShoulderRoll
    {-2.08567, 2.08567},     // LElbowYaw
    {-1.54462, -0.0349066},  // LElbowRoll
    {-1.82387, 1.82387},     // LWristYaw
    {-1.14529, 0.740718},    // LHipYawPitch
    {-0.379435, 0.79046},    // LHipRoll
    {-1.53589, 0.48398},     // LHipPitch
    {-0.0923279, 2.11255},   // LKneePitch
    {-1.18944, 0.922581},    // LAnklePitch
    {-0.397761, 0.768992},   // LAnkleRoll
    {-0.79046, 0.379435},    // RHipRoll
    {-1.53589, 0.48398},     // RHipPitch
    {-0.0923279, 2.11255},   // RKneePitch
    {-1.18944, 0.922581},    // RAnklePitch
    {-0.768992, 0.397761},   // RAnkleRoll
    {-2.08567, 2.08567},     // RShoulderPitch
    {-1.32645, 0.314159},    // RShoulderRoll
    {-2.08567, 2.08567},     // RElbowYaw
    {0.0349066, 1.54462},    // RElbowRoll
    {-1.82387, 1.82387},     // RWristYaw
    {0.0, 1.0},              // LHand
    {0.0, 1.0},              // RHand
}};

}  // namespace stride::nao
