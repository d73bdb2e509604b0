#include "simulator/teleport.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "robot/core/error.hpp"

namespace stride::sim {

void teleport_robot(Simulation& sim, int robot, const Eigen::Vector3d& position, double yaw) {
  if (robot < 0 || robot >= sim.robot_count())
    throw Error("teleport: no robot " + std::to_string(robot));
  if (!position.allFinite() || !std::isfinite(yaw))
    throw Error("teleport: position must be finite");
  SimulatedRobot& r = sim.robot(robot);
  const TorsoPose now = r.torso_pose();
  const Eigen::Vector3d from(now.x, now.y, now.z);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(yaw - now.yaw, Eigen::Vector3d::UnitZ()).matrix();
  const RobotBody& body = r.body();
  for (int link = 0; link < body.link_count(); ++link) {
    dBodyID b = body.body(link);
    if (!b) continue;
    const dReal* p = dBodyGetPosition(b);
    const Eigen::Vector3d moved = position + turn * (Eigen::Vector3d(p[0], p[1], p[2]) - from);
    const dReal* q = dBodyGetRotation(b);  // ODE: 3x4 row-major
    Eigen::Matrix3d rot;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) rot(i, j) = q[i * 4 + j];
    const Eigen::Matrix3d turned = turn * rot;
    dMatrix3 out;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) out[i * 4 + j] = turned(i, j);
      out[i * 4 + 3] = 0;
    }
    dBodySetPosition(b, moved.x(), moved.y(), moved.z());
    dBodySetRotation(b, out);
    dBodySetLinearVel(b, 0, 0, 0);
    dBodySetAngularVel(b, 0, 0, 0);
  }
}

}  // namespace stride::sim
