#pragma once
// Stand: provides a JointRequest that holds the standing posture, reached from the measured pose
// by a short smooth interpolation when the module starts.
#include <array>

#include "robot/framework/module_registry.hpp"
#include "robot/hal/joint_id.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::behaviours {

// Left-side angles; the right side is mirrored where the joint is (roll and yaw joints).
// Ranges are the joint limits of nao-facts.md.
struct StandParameters {
  double hip_pitch = nao::kStandHipPitch;
  double knee_pitch = nao::kStandKneePitch;
  double ankle_pitch = nao::kStandAnklePitch;
  double shoulder_pitch = 1.5;  // arms hanging down
  double shoulder_roll = 0.1;   // slightly away from the body
  double elbow_yaw = 0.0;
  double elbow_roll = -0.05;  // nearly straight
  double stiffness = 0.8;
  double interpolation_time = 1.0;  // from the measured pose to the posture

  static constexpr std::string_view kTypeName = "StandParameters";
  static constexpr auto fields() {
    using P = StandParameters;
    return std::make_tuple(
        field("hip_pitch", &P::hip_pitch, "rad", Range{-1.53589, 0.48398}),
        field("knee_pitch", &P::knee_pitch, "rad", Range{-0.0923279, 2.11255}),
        field("ankle_pitch", &P::ankle_pitch, "rad", Range{-1.18944, 0.922581}),
        field("shoulder_pitch", &P::shoulder_pitch, "rad", Range{-2.08567, 2.08567}),
        field("shoulder_roll", &P::shoulder_roll, "rad", Range{-0.314159, 1.32645}),
        field("elbow_yaw", &P::elbow_yaw, "rad", Range{-2.08567, 2.08567}),
        field("elbow_roll", &P::elbow_roll, "rad", Range{-1.54462, -0.0349066}),
        field("stiffness", &P::stiffness, "", Range{0, 1}),
        field("interpolation_time", &P::interpolation_time, "s", Range{0, 10}));
  }
};

// The posture's joint angles in LoLA order.
std::array<double, hal::kNumJoints> stand_posture(const StandParameters& p);

void register_stand(ModuleRegistry& registry);

}  // namespace stride::behaviours
