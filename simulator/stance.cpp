#include "simulator/stance.hpp"

#include <algorithm>

namespace stride::sim {

std::array<Eigen::Vector2d, 2> foot_positions(const RobotBody& body) {
  const auto& m = body.model();
  return {body.link_pose(m.link_index("LFoot")).translation().head<2>(),
          body.link_pose(m.link_index("RFoot")).translation().head<2>()};
}

SagittalState sagittal_com_state(const RobotBody& body) {
  const Eigen::Vector3d p = body.centre_of_mass(), v = body.centre_of_mass_velocity();
  const auto feet = foot_positions(body);
  return {p.x() - 0.5 * (feet[0].x() + feet[1].x()), v.x()};
}

double foot_motion(const std::array<Eigen::Vector2d, 2>& before,
                   const std::array<Eigen::Vector2d, 2>& after) {
  double motion = 0;
  for (int i = 0; i < 2; ++i) motion = std::max(motion, (after[i] - before[i]).norm());
  return motion;
}

}  // namespace stride::sim
