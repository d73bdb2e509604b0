#include "simulator/teleport.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "robot/core/error.hpp"
#include "robot/core/physical_limits.hpp"

namespace stride::sim {
namespace {
constexpr double kMaxYaw = 1e3;  // rad
}  // namespace

void teleport_robot(Simulation& sim, int robot, const Eigen::Vector3d& position, double yaw) {
  if (robot < 0 || robot >= sim.robot_count())
    throw Error("teleport: no robot " + std::to_string(robot));
  for (int k = 0; k < 3; ++k)
    if (!(std::abs(position[k]) <= limits::kMaxPosition)) {
      std::ostringstream msg;
      msg << "mv: "
          << "xyz"[k] << " " << position[k] << " m outside [" << -limits::kMaxPosition << ", "
          << limits::kMaxPosition << "]";
      throw Error(msg.str());
    }
  if (!(std::abs(yaw) <= kMaxYaw)) {
    std::ostringstream msg;
    msg << "mv: yaw " << yaw << " rad outside [" << -kMaxYaw << ", " << kMaxYaw << "]";
    throw Error(msg.str());
  }
  SimulatedRobot& r = sim.robot(robot);
  const TorsoPose now = r.torso_pose();
  const Eigen::Vector3d from(now.x, now.y, now.z);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw - now.yaw, Eigen::Vector3d::UnitZ()).matrix();
  r.mutable_body().move_rigidly(from, position, turn);
}

}  // namespace stride::sim
