#pragma once
// A RobotModel as a physics engine's bodies and joints: what devices, pushes, metrics and the
// teleport read and drive. Link indices and joint indices are the model's.
#include <functional>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "robot/model/link_poses.hpp"
#include "robot/model/robot_model.hpp"

namespace stride::sim {

class RobotBody {
 public:
  explicit RobotBody(const model::RobotModel& model) : model_(model) {}
  virtual ~RobotBody() = default;
  RobotBody(const RobotBody&) = delete;
  RobotBody& operator=(const RobotBody&) = delete;

  const model::RobotModel& model() const { return model_; }
  int link_count() const { return static_cast<int>(model_.links.size()); }

  virtual Eigen::Isometry3d link_pose(int link) const = 0;  // world frame
  virtual Eigen::Vector3d link_com(int link) const = 0;     // world frame
  virtual Eigen::Vector3d link_com_velocity(int link) const = 0;
  virtual Eigen::Vector3d link_angular_velocity(int link) const = 0;  // world frame
  // Velocity of the link's material point now at world point `p`.
  virtual Eigen::Vector3d point_velocity(int link, const Eigen::Vector3d& p) const = 0;
  // Force and torque (world frame) queued on the link for the next step.
  virtual std::pair<Eigen::Vector3d, Eigen::Vector3d> queued_load(int link) const = 0;

  virtual bool is_hinge(int j) const = 0;
  virtual double joint_position(int j) const = 0;
  virtual double joint_velocity(int j) const = 0;
  // Torque the joint's motor and limits applied during the last step, about the joint axis.
  virtual double joint_constraint_torque(int j) const = 0;
  // An engine may drop a hinge's stops while the joint (at `q`) is far from both; a no-op else.
  virtual void keep_stops_within_reach(int j, double q) = 0;

  // Hinge motor: drive the joint toward `speed` (rad/s) with at most `max_torque` (N m). The
  // softness (ODE's motor CFM, rad/s per N m) makes the motor a spring; engines without it refuse.
  virtual void set_motor_speed(int j, double speed) = 0;
  virtual void set_motor_softness(int j, double softness) = 0;
  virtual void set_motor_max_torque(int j, double max_torque) = 0;
  virtual void add_joint_torque(int j, double torque) = 0;
  // A force (world frame) at `at` in the link frame, for the next step.
  virtual void add_force(int link, const Eigen::Vector3d& force, const Eigen::Vector3d& at) = 0;

  // Weld the root link to the world where it stands.
  virtual void fix_to_world() = 0;
  // Move every body rigidly: p -> to + turn (p - from); velocities cleared.
  virtual void move_rigidly(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                            const Eigen::Matrix3d& turn) = 0;
  // Every number of the dynamic state, in a fixed order, for the determinism hash.
  virtual void visit_state(const std::function<void(const double*, int)>& f) const = 0;

  // Whole-robot centre of mass in the world frame (mass-weighted body positions).
  Eigen::Vector3d centre_of_mass() const;
  // Its velocity (mass-weighted body velocities), world frame.
  Eigen::Vector3d centre_of_mass_velocity() const;

 private:
  const model::RobotModel& model_;
};

}  // namespace stride::sim
