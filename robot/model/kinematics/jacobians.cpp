#include "robot/model/kinematics/jacobians.hpp"

#include "robot/model/kinematics/nao_fk.hpp"

namespace stride::model {
namespace {

// Column of a revolute (or prismatic) joint for a point p, both in the root frame.
void joint_column(const Joint& jt, const Eigen::Isometry3d& child_pose, const Eigen::Vector3d& p,
                  double scale, Eigen::Ref<Eigen::Matrix<double, 6, 1>> col) {
  const Eigen::Vector3d axis = child_pose.linear() * jt.axis;
  if (jt.type == JointType::Prismatic) {
    col.head<3>() += scale * axis;
    return;
  }
  col.head<3>() += scale * axis.cross(p - child_pose.translation());  // Eq. D.9
  col.tail<3>() += scale * axis;                                      // Eq. D.5
}

// Column that receives joint j's effect and the chain-rule factor (mimic joints follow a master).
int column_of(const RobotModel& model, int j, double& scale) {
  const Joint& jt = model.joints[j];
  scale = jt.mimic_of >= 0 ? jt.mimic_multiplier : 1.0;
  return jt.mimic_of >= 0 ? jt.mimic_of : j;
}

}  // namespace

void geometric_jacobian(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses,
                        int link, const Eigen::Vector3d& point_in_link, Jacobian6& out) {
  out.setZero();
  const Eigen::Vector3d p = poses[link] * point_in_link;
  for (int l = link; model.links[l].parent_joint >= 0;) {
    const int j = model.links[l].parent_joint;
    const Joint& jt = model.joints[j];
    if (jt.movable()) {
      double scale;
      const int c = column_of(model, j, scale);
      joint_column(jt, poses[jt.child_link], p, scale, out.col(c));
    }
    l = jt.parent_link;
  }
}

void com_jacobian(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses,
                  Eigen::Matrix3Xd& out) {
  out.setZero();
  double total = 0;
  for (const Link& l : model.links) total += l.inertial.mass;
  if (total <= 0) return;
  // Each link's mass pulls on every joint between it and the root (the CoM of Eq. 3.17,
  // differentiated).
  for (size_t i = 0; i < model.links.size(); ++i) {
    const Inertial& in = model.links[i].inertial;
    if (in.mass <= 0) continue;
    const Eigen::Vector3d c = poses[i] * in.com;
    const double w = in.mass / total;
    for (int l = static_cast<int>(i); model.links[l].parent_joint >= 0;) {
      const int j = model.links[l].parent_joint;
      const Joint& jt = model.joints[j];
      if (jt.movable()) {
        double scale;
        const int col = column_of(model, j, scale);
        const Eigen::Vector3d axis = poses[jt.child_link].linear() * jt.axis;
        out.col(col) += w * scale *
                        (jt.type == JointType::Prismatic
                             ? axis
                             : Eigen::Vector3d(axis.cross(c - poses[jt.child_link].translation())));
      }
      l = jt.parent_link;
    }
  }
}

Matrix6d leg_jacobian(Side side, const LegAngles& q) {
  std::array<Eigen::Isometry3d, 7> f;
  leg_dh_frames(side, q, f);
  const Eigen::Vector3d p = f[6].translation();
  Matrix6d j;
  for (int i = 0; i < kLegJoints; ++i) {
    const Eigen::Vector3d z = leg_dh_sign(side, i) * f[i].linear().col(2);  // Eq. D.6
    j.col(i).head<3>() = z.cross(p - f[i].translation());                   // Eq. D.9
    j.col(i).tail<3>() = z;                                                 // Eq. D.5
  }
  return j;
}

Matrix6d leg_jacobian_in_foot(Side side, const LegAngles& q) {
  const Eigen::Matrix3d r = leg_fk(side, q).linear().transpose();
  Matrix6d j = leg_jacobian(side, q);
  j.topRows<3>() = r * j.topRows<3>();
  j.bottomRows<3>() = r * j.bottomRows<3>();
  return j;
}

Matrix6d torso_jacobian_in_foot(Side side, const LegAngles& q) {
  std::array<Eigen::Isometry3d, 7> f;
  leg_dh_frames(side, q, f);
  const Eigen::Isometry3d to_foot = f[6].inverse();
  const Eigen::Vector3d torso = to_foot.translation();  // torso origin in the sole frame
  Matrix6d j;
  for (int i = 0; i < kLegJoints; ++i) {
    const Eigen::Vector3d z = -leg_dh_sign(side, i) * (to_foot.linear() * f[i].linear().col(2));
    const Eigen::Vector3d o = to_foot * f[i].translation();
    j.col(i) << z.cross(torso - o), z;
  }
  return j;
}

}  // namespace stride::model
