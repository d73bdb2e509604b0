#pragma once
// Generic forward kinematics over any RobotModel tree: every link frame in the root link's frame.
#include <vector>

#include <Eigen/Geometry>

#include "robot/model/robot_model.hpp"

namespace stride::model {

// Joint values indexed like model.joints (fixed joints ignored). Mimic joints follow their master.
using JointVector = Eigen::VectorXd;

JointVector zero_joints(const RobotModel& model);
void apply_mimic(const RobotModel& model, JointVector& q);

// Pose of one joint's child frame relative to its parent link for the joint value qi.
Eigen::Isometry3d joint_transform(const Joint& joint, double qi);

// Link frames in the root frame; out is resized to model.links.size().
void link_poses(const RobotModel& model, const JointVector& q, std::vector<Eigen::Isometry3d>& out);

// Whole-body centre of mass in the root frame.
Eigen::Vector3d centre_of_mass(const RobotModel& model,
                               const std::vector<Eigen::Isometry3d>& poses);

}  // namespace stride::model
