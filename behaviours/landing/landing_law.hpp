#pragma once
// Thesis Ch. 6's landing foot as pure functions: the sole's planned descent, the impedance law of
// The impedance law of Eq. 6.17 and the gravity term g(theta) it adds, for the NAO's left leg in
// the torso frame.
#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "robot/model/kinematics/jacobians.hpp"
#include "robot/model/robot_model.hpp"

namespace stride::landing {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Where the sole should be at time t: its starting pose, sunk at `speed` until `end_z`.
struct SoleTarget {
  Eigen::Isometry3d pose;
  Eigen::Vector3d velocity;  // m/s
};
SoleTarget planned_sole(const Eigen::Isometry3d& start, double speed, double end_z, double t);

struct ImpedanceGains {
  Eigen::Vector3d stiffness{2000, 2000, 300};  // K, N/m (x, y, z in the torso frame)
  Eigen::Vector3d damping{20, 20, 15};         // B, N s/m
  double rot_stiffness = 20;                   // N m/rad
  double rot_damping = 0.3;                    // N m s/rad
};

// tau = J^T (B (x'_d - x') + K (x_d - x)) + g(theta) (Eq. 6.17); `q`, `qd` the leg's six joints
// (HipYawPitch first), `gravity` the g(theta) term (leg_gravity_torques).
model::LegAngles impedance_torques(const ImpedanceGains& gains, const SoleTarget& target,
                                   const model::LegAngles& q, const model::LegAngles& qd,
                                   const model::LegAngles& gravity);

// The motor torques that hold the left leg's own weight (g(theta)), leg joint order: joint j
// carries every link from its child link down to the foot. `q_model` is indexed like
// model.joints; `gravity` is the gravity vector in the torso (root) frame.
struct LegGravityModel {
  std::array<int, 6> joint{};                 // model joint of each leg joint
  std::array<std::array<int, 6>, 6> links{};  // child links joint j carries (-1: none)
};
LegGravityModel left_leg_gravity_model(const model::RobotModel& model);
model::LegAngles leg_gravity_torques(const model::RobotModel& model, const LegGravityModel& leg,
                                     const Eigen::VectorXd& q_model,
                                     const Eigen::Vector3d& gravity);
// The same with the link poses computed into `poses` (sized once by the caller's first call, so
// a control frame that keeps it does not allocate).
model::LegAngles leg_gravity_torques(const model::RobotModel& model, const LegGravityModel& leg,
                                     const Eigen::VectorXd& q_model, const Eigen::Vector3d& gravity,
                                     std::vector<Eigen::Isometry3d>& poses);

}  // namespace stride::landing
