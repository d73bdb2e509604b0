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
  STRIDE_FIELDS(StandParameters);
  STRIDE_FIELD(double, hip_pitch, "rad", Range{-1.53589, 0.48398}) = nao::kStandHipPitch;
  STRIDE_FIELD(double, knee_pitch, "rad", Range{-0.0923279, 2.11255}) = nao::kStandKneePitch;
  STRIDE_FIELD(double, ankle_pitch, "rad", Range{-1.18944, 0.922581}) = nao::kStandAnklePitch;
  STRIDE_FIELD(double, shoulder_pitch, "rad", Range{-2.08567, 2.08567}) = 1.5;  // arms hanging down
  // slightly away from the body
  STRIDE_FIELD(double, shoulder_roll, "rad", Range{-0.314159, 1.32645}) = 0.1;
  STRIDE_FIELD(double, elbow_yaw, "rad", Range{-2.08567, 2.08567}) = 0.0;
  STRIDE_FIELD(double, elbow_roll, "rad", Range{-1.54462, -0.0349066}) = -0.05;  // nearly straight
  STRIDE_FIELD(double, stiffness, "", Range{0, 1}) = 0.8;
  // from the measured pose to the posture
  STRIDE_FIELD(double, interpolation_time, "s", Range{0, 10}) = 1.0;

  static constexpr std::string_view kTypeName = "StandParameters";
};

// The posture's joint angles in LoLA order.
std::array<double, hal::kNumJoints> stand_posture(const StandParameters& p);

void register_stand(ModuleRegistry& registry);

}  // namespace stride::behaviours
