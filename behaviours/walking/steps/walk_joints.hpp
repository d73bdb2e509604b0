#pragma once
// Leg joint angles of an online walk sample: each flat sole relative to the upright torso, the
// torso yawed where the shared HipYawPitch reaches both feet (model::legs_ik_turned).
#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "behaviours/walking/steps/online_walk.hpp"

namespace stride::walking {

struct WalkJoints {
  LegJoints legs;
  double torso_yaw = 0.0;  // world; near the mean of the feet's yaws
  double yaw_error = 0.0;  // rad of the right foot's yaw not reached (0 within a turn's reach)
};

WalkJoints leg_joints(const WalkSample& s);

}  // namespace stride::walking
