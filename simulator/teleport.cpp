#include "simulator/teleport.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "robot/core/error.hpp"
#include "robot/model/physical_limits.hpp"

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
