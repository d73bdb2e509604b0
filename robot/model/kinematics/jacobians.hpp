#pragma once
// Jacobians (thesis App. D): generic geometric and centre-of-mass Jacobians over any RobotModel,
// and the analytic 6x6 NAO leg Jacobians from the D-H frames. Twists are stacked [v; omega].
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "robot/model/kinematics/nao_chains.hpp"
#include "robot/model/robot_model.hpp"

namespace stride::model {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Jacobian6 = Eigen::Matrix<double, 6, Eigen::Dynamic>;

// Twist of a point fixed in `link` in the root frame per joint velocity (Eq. D.5, Eq. D.9): one
// column per model joint; a mimic joint's effect is added to its master's column, so columns of
// mimic and fixed joints stay zero. out must be 6 x model.joints.size() (not resized).
void geometric_jacobian(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses,
                        int link, const Eigen::Vector3d& point_in_link, Jacobian6& out);

// d(centre of mass)/dq (of Eq. 3.17) in the root frame, 3 x model.joints.size(), mimic folded
// into the master column as above. out must be sized by the caller.
void com_jacobian(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses,
                  Eigen::Matrix3Xd& out);

// Sole twist in the torso frame per leg joint velocity (J of Eq. D.3, its columns by Eq. D.5,
// Eq. D.6 and Eq. D.9); columns in leg order.
Matrix6d leg_jacobian(Side side, const LegAngles& q);

// The same twist expressed in the sole frame (the end-effector form of Eq. D.10).
Matrix6d leg_jacobian_in_foot(Side side, const LegAngles& q);

// Twist of the torso relative to a standing sole, expressed in the sole frame (FCS): the chain
// walked from the foot up, every joint turning the other way (Table B.8, FCS column).
Matrix6d torso_jacobian_in_foot(Side side, const LegAngles& q);

}  // namespace stride::model
