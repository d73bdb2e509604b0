#pragma once
// Numeric inverse kinematics for any chain of a RobotModel by damped least squares (Levenberg-
// Marquardt style): used for the arms and anything without a closed form.
#include <vector>

#include <Eigen/Geometry>

#include "robot/model/kinematics/jacobians.hpp"
#include "robot/model/link_poses.hpp"

namespace stride::model {

struct DlsIkOptions {
  int max_iterations = 200;
  double damping = 1e-4;          // lambda: bounds the step near singular postures
  double tolerance = 1e-12;       // stop when |error| (m and rad, stacked) falls below
  double orientation_weight = 1;  // 0: position only
  bool respect_limits = true;     // clamp every step to the URDF joint limits
};

struct DlsIkResult {
  bool converged = false;
  int iterations = 0;
  double error = 0;  // final |[position error; weight * orientation error]|
};

// Scratch space so that repeated calls do not allocate.
struct DlsIkWorkspace {
  std::vector<Eigen::Isometry3d> poses;
  Jacobian6 jacobian;
};

// Moves q (model joint vector, in/out) so that the point `point_in_link` of `link` with the link's
// orientation reaches `target` (root frame). Only joints between the root and the link move.
DlsIkResult dls_ik(const RobotModel& model, int link, const Eigen::Isometry3d& target,
                   JointVector& q, DlsIkWorkspace& work, const DlsIkOptions& options = {},
                   const Eigen::Vector3d& point_in_link = Eigen::Vector3d::Zero());

}  // namespace stride::model
