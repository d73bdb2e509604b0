#include "behaviours/landing/landing_law.hpp"

#include <algorithm>
#include <vector>

#include "robot/core/error.hpp"
#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/model/link_poses.hpp"

namespace stride::landing {

SoleTarget planned_sole(const Eigen::Isometry3d& start, double speed, double end_z, double t) {
  SoleTarget s{start, Eigen::Vector3d::Zero()};
  s.pose.translation().z() = std::max(end_z, start.translation().z() - speed * t);
  if (s.pose.translation().z() > end_z) s.velocity.z() = -speed;
  return s;
}

model::LegAngles impedance_torques(const ImpedanceGains& k, const SoleTarget& target,
                                   const model::LegAngles& q, const model::LegAngles& qd,
                                   const model::LegAngles& gravity) {
  const Eigen::Isometry3d x = model::leg_fk(model::Side::Left, q);
  const model::Matrix6d j = model::leg_jacobian(model::Side::Left, q);
  const Vector6d xd = j * Eigen::Map<const Vector6d>(qd.data());  // sole twist [v; omega]
  Vector6d wrench;  // B (x'_d - x') + K (x_d - x) of Eq. 6.17
  wrench.head<3>() = k.stiffness.cwiseProduct(target.pose.translation() - x.translation()) +
                     k.damping.cwiseProduct(target.velocity - xd.head<3>());
  const Eigen::AngleAxisd rot(target.pose.linear() * x.linear().transpose());
  wrench.tail<3>() = k.rot_stiffness * rot.angle() * rot.axis() - k.rot_damping * xd.tail<3>();
  const Vector6d tau = j.transpose() * wrench;
  model::LegAngles out{};
  for (int i = 0; i < 6; ++i) out[i] = tau[i] + gravity[i];  // Eq. 6.17
  return out;
}

LegGravityModel left_leg_gravity_model(const model::RobotModel& m) {
  constexpr std::array<const char*, 6> kJoints = {"LHipYawPitch", "LHipRoll",    "LHipPitch",
                                                  "LKneePitch",   "LAnklePitch", "LAnkleRoll"};
  constexpr std::array<const char*, 6> kChildLinks = {"LPelvis", "LHip",   "LThigh",
                                                      "LTibia",  "LAnkle", "LFoot"};
  LegGravityModel leg;
  for (int j = 0; j < 6; ++j) {
    leg.joint[j] = m.joint_index(kJoints[j]);
    if (leg.joint[j] < 0) throw Error(m.source + ": no joint " + kJoints[j] + " (a NAO left leg)");
    leg.links[j].fill(-1);
    for (int k = j; k < 6; ++k) {
      leg.links[j][k] = m.link_index(kChildLinks[k]);
      if (leg.links[j][k] < 0)
        throw Error(m.source + ": no link " + kChildLinks[k] + " (a NAO left leg)");
    }
  }
  return leg;
}

model::LegAngles leg_gravity_torques(const model::RobotModel& m, const LegGravityModel& leg,
                                     const Eigen::VectorXd& q_model,
                                     const Eigen::Vector3d& gravity) {
  std::vector<Eigen::Isometry3d> poses;
  return leg_gravity_torques(m, leg, q_model, gravity, poses);
}

model::LegAngles leg_gravity_torques(const model::RobotModel& m, const LegGravityModel& leg,
                                     const Eigen::VectorXd& q_model, const Eigen::Vector3d& gravity,
                                     std::vector<Eigen::Isometry3d>& poses) {
  model::link_poses(m, q_model, poses);
  model::LegAngles g{};
  for (int j = 0; j < 6; ++j) {
    const model::Joint& joint = m.joints[leg.joint[j]];
    const Eigen::Isometry3d& frame = poses[joint.child_link];
    const Eigen::Vector3d axis = frame.linear() * joint.axis;
    Eigen::Vector3d torque = Eigen::Vector3d::Zero();
    for (int l : leg.links[j]) {
      if (l < 0) continue;
      const Eigen::Vector3d com = poses[l] * m.links[l].inertial.com;
      torque += (com - frame.translation()).cross(m.links[l].inertial.mass * gravity);
    }
    g[j] = -torque.dot(axis);  // the motor opposes gravity
  }
  return g;
}

}  // namespace stride::landing
