#pragma once
// Ground truth of a robot standing on its two feet: where the feet are, the CoM's sagittal state
// in the ground frame the Ch. 7 balance models use (origin midway between the ankles), and how
// far the feet moved (a recovery in place keeps them still).
#include <array>

#include <Eigen/Core>

#include "simulator/world/robot_body.hpp"

namespace stride::sim {

// The LFoot and RFoot link origins in the world, (x, y).
std::array<Eigen::Vector2d, 2> foot_positions(const RobotBody& body);

struct SagittalState {
  double x = 0;  // m, CoM ahead of the ankles' midpoint along the world x axis
  double v = 0;  // m/s, CoM velocity along x
};
SagittalState sagittal_com_state(const RobotBody& body);

// The larger horizontal displacement of the two feet between two foot_positions().
double foot_motion(const std::array<Eigen::Vector2d, 2>& before,
                   const std::array<Eigen::Vector2d, 2>& after);

}  // namespace stride::sim
