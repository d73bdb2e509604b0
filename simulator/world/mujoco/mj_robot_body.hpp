#pragma once
// A robot in the MuJoCo world, read and driven through the compiled model's ids. Link frames are
// MuJoCo body frames (inertials are offset inside them), so no centre-of-mass shift is needed.
#include "simulator/world/mujoco/mj_world.hpp"
#include "simulator/world/robot_body.hpp"

namespace stride::sim {

class MjRobotBody : public RobotBody {
 public:
  MjRobotBody(MjWorld& world, const model::RobotModel& model, int slot);

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
  void keep_stops_within_reach(int, double) override {}  // MuJoCo activates limits itself

  void set_motor_speed(int j, double speed) override;
  // No soft motor in MuJoCo: robots whose servos need one are refused when the scene is built.
  void set_motor_softness(int j, double softness) override;
  // Ends a motor's setting for this step (see the .cpp for the implicit servo).
  void set_motor_max_torque(int j, double max_torque) override;
  void add_joint_torque(int j, double torque) override;
  void add_force(int link, const Eigen::Vector3d& force, const Eigen::Vector3d& at) override;

  void fix_to_world() override;
  void move_rigidly(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                    const Eigen::Matrix3d& turn) override;
  void visit_state(const std::function<void(const double*, int)>& f) const override;

 private:
  int body(int link) const { return world_.layout(slot_).body[link]; }
  int dof(int j) const { return world_.layout(slot_).dof[j]; }
  // World-frame angular and linear velocity of the link frame's origin.
  std::pair<Eigen::Vector3d, Eigen::Vector3d> frame_velocity(int link) const;

  MjWorld& world_;
  int slot_;
};

}  // namespace stride::sim
