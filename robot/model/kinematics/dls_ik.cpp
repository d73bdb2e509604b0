#include "robot/model/kinematics/dls_ik.hpp"

#include <algorithm>

#include <Eigen/Cholesky>

namespace stride::model {

DlsIkResult dls_ik(const RobotModel& model, int link, const Eigen::Isometry3d& target,
                   JointVector& q, DlsIkWorkspace& work, const DlsIkOptions& options,
                   const Eigen::Vector3d& point_in_link) {
  const auto n = static_cast<Eigen::Index>(model.joints.size());
  work.jacobian.resize(6, n);
  DlsIkResult result;
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  const auto pose_error = [&](Vector6d& e) {
    link_poses(model, q, work.poses);
    const Eigen::Isometry3d& pose = work.poses[link];
    e.head<3>() = target.translation() - pose * point_in_link;
    const Eigen::AngleAxisd rot(target.linear() * pose.linear().transpose());
    e.tail<3>() = options.orientation_weight * rot.angle() * rot.axis();
    return e.norm();
  };
  Vector6d e;
  apply_mimic(model, q);
  result.error = pose_error(e);
  for (; result.iterations < options.max_iterations && result.error > options.tolerance;
       ++result.iterations) {
    geometric_jacobian(model, work.poses, link, point_in_link, work.jacobian);
    work.jacobian.bottomRows<3>() *= options.orientation_weight;
    // dq = J^T (J J^T + lambda^2 I)^-1 e: a 6x6 solve whatever the chain length.
    Eigen::Matrix<double, 6, 6> jjt = work.jacobian * work.jacobian.transpose();
    jjt.diagonal().array() += options.damping * options.damping;
    const Vector6d y = jjt.ldlt().solve(e);
    q.noalias() += work.jacobian.transpose() * y;
    if (options.respect_limits)
      for (Eigen::Index j = 0; j < n; ++j) {
        const Joint& jt = model.joints[j];
        if (jt.actuated() && jt.type != JointType::Continuous && jt.lower < jt.upper)
          q[j] = std::clamp(q[j], jt.lower, jt.upper);
      }
    apply_mimic(model, q);
    result.error = pose_error(e);
  }
  result.converged = result.error <= options.tolerance;
  return result;
}

}  // namespace stride::model
