#pragma once
// A RobotModel made of ODE bodies, hinge joints and collision geoms. ODE wants each body's origin
// at its centre of mass, so a body sits at link frame * com; link poses are converted back here.
#include <vector>

#include <ode/ode.h>

#include "simulator/world/ode/ode_world.hpp"
#include "simulator/world/robot_body.hpp"

namespace stride::sim {

class OdeRobotBody : public RobotBody {
 public:
  // Builds the robot with its root link at `root_pose` and joints at `q` (mimic applied).
  OdeRobotBody(OdeWorld& world, const model::RobotModel& model, int robot_index,
               const Eigen::Isometry3d& root_pose, const model::JointVector& q);

  dBodyID body(int link) const { return bodies_[link]; }
  dJointID joint(int j) const { return joints_[j]; }

  Eigen::Isometry3d link_pose(int link) const override;
  Eigen::Vector3d link_com(int link) const override;
  Eigen::Vector3d link_com_velocity(int link) const override;
  Eigen::Vector3d link_angular_velocity(int link) const override;
  Eigen::Vector3d point_velocity(int link, const Eigen::Vector3d& p) const override;
  std::pair<Eigen::Vector3d, Eigen::Vector3d> queued_load(int link) const override;

  bool is_hinge(int j) const override;
  double joint_position(int j) const override;
  double joint_velocity(int j) const override;
  double joint_constraint_torque(int j) const override;
  // ODE works out every limited hinge's angle each step to test its stops. Far from both stops
  // (`q` is the joint's angle now) the hinge is given none, which changes nothing (no limit row
  // either way) but spares that work; within reach they are back in place.
  void keep_stops_within_reach(int j, double q) override;

  void set_motor_speed(int j, double speed) override;
  void set_motor_softness(int j, double softness) override;
  void set_motor_max_torque(int j, double max_torque) override;
  void add_joint_torque(int j, double torque) override;
  void add_force(int link, const Eigen::Vector3d& force, const Eigen::Vector3d& at) override;

  void fix_to_world() override;
  void move_rigidly(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                    const Eigen::Matrix3d& turn) override;
  void visit_state(const std::function<void(const double*, int)>& f) const override;

 private:
  dWorldID world_;
  std::vector<dBodyID> bodies_;
  std::vector<dJointID> joints_;
  std::vector<dJointFeedback> feedback_;
  std::vector<char> stops_set_;  // per joint: ODE has the model's stops
};

Eigen::Isometry3d to_isometry(const dReal* pos, const dReal* rot);

}  // namespace stride::sim
