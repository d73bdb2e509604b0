#pragma once
// A RobotModel made of ODE bodies, hinge joints and collision geoms. ODE wants each body's origin
// at its centre of mass, so a body sits at link frame * com; link poses are converted back here.
#include <string>
#include <vector>

#include <ode/ode.h>
#include <Eigen/Geometry>

#include "robot/model/link_poses.hpp"
#include "robot/model/robot_model.hpp"
#include "simulator/world/physics_world.hpp"

namespace stride::sim {

class RobotBody {
 public:
  // Builds the robot with its root link at `root_pose` and joints at `q` (mimic applied).
  RobotBody(PhysicsWorld& world, const model::RobotModel& model, int robot_index,
            const Eigen::Isometry3d& root_pose, const model::JointVector& q);
  RobotBody(const RobotBody&) = delete;
  RobotBody& operator=(const RobotBody&) = delete;

  const model::RobotModel& model() const { return model_; }
  int link_count() const { return static_cast<int>(bodies_.size()); }
  dBodyID body(int link) const { return bodies_[link]; }
  dJointID joint(int j) const { return joints_[j]; }  // nullptr for fixed joints

  Eigen::Isometry3d link_pose(int link) const;  // world frame
  Eigen::Vector3d link_com(int link) const;     // world frame
  double joint_position(int j) const;
  double joint_velocity(int j) const;
  // Torque the joint's motor and limits applied during the last step, about the joint axis.
  double joint_constraint_torque(int j) const;

  // ODE works out every limited hinge's angle each step to test its stops. Far from both stops
  // (`q` is the joint's angle now) the hinge is given none, which changes nothing (no limit row
  // either way) but spares that work; within reach they are back in place.
  void keep_stops_within_reach(int j, double q);

  // Whole-robot centre of mass in the world frame (mass-weighted body positions).
  Eigen::Vector3d centre_of_mass() const;
  // Its velocity (mass-weighted body velocities), world frame.
  Eigen::Vector3d centre_of_mass_velocity() const;

 private:
  const model::RobotModel& model_;
  std::vector<dBodyID> bodies_;
  std::vector<dJointID> joints_;
  std::vector<dJointFeedback> feedback_;
  std::vector<char> stops_set_;  // per joint: ODE has the model's stops
};

Eigen::Isometry3d to_isometry(const dReal* pos, const dReal* rot);

}  // namespace stride::sim
