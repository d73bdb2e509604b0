#pragma once
// Moving a robot as a rigid whole (console `mv`): its posture is kept, its velocities cleared.
#include "simulator/simulation.hpp"

namespace stride::sim {

// Puts robot `robot`'s torso origin at (x, y, z) with heading `yaw` (rad), rotating the whole
// robot about the vertical; roll and pitch are kept. Throws stride::Error for a bad index.
void teleport_robot(Simulation& sim, int robot, const Eigen::Vector3d& position, double yaw);

}  // namespace stride::sim
