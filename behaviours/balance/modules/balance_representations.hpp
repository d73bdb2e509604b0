#pragma once
// Representations of the standing-balance modules (thesis Ch. 7): the estimated CoM state and the
// robot's numbers for the inverted-pendulum models, both in the ground frame between the feet.
#include <array>
#include <string_view>

#include <Eigen/Core>

#include "behaviours/balance/balance_params.hpp"
#include "robot/framework/reflect.hpp"

namespace stride {

// Where the ground frame of ComState has its origin: midway between the two sole points (standing)
// or under the sole that carries the robot (walking: the stance foot, chosen by the FSRs).
enum class GroundOrigin { between_feet, left_sole, right_sole };
template <>
struct EnumNames<GroundOrigin> {
  static constexpr std::string_view type_name = "GroundOrigin";
  static constexpr std::array<std::string_view, 3> names{"between_feet", "left_sole", "right_sole"};
};

// Ground frame: origin midway between the two sole points (below the ankles), axes of the left
// sole (x forward, z up); the thesis' x_cm and the ZMP are measured from the ankle like this.
struct ComState {
  STRIDE_FIELDS(ComState);
  // false until the filter has seen joints and a centre of pressure
  STRIDE_FIELD(bool, valid) = false;
  // filtered CoM state (Sec. 7.2)
  STRIDE_FIELD(double, x, "m") = 0;
  STRIDE_FIELD(double, xdot, "m/s") = 0;
  STRIDE_FIELD(double, y, "m") = 0;
  STRIDE_FIELD(double, ydot, "m/s") = 0;
  // filtered ZMP
  STRIDE_FIELD(double, zmp_x, "m") = 0;
  STRIDE_FIELD(double, zmp_y, "m") = 0;
  // kinematic CoM height z0 above the soles
  STRIDE_FIELD(double, com_height, "m") = 0;
  // kinematic CoM, this frame
  STRIDE_FIELD(Eigen::Vector3d, measured_com, "m") = Eigen::Vector3d::Zero();
  // FSR centre of pressure, this frame
  STRIDE_FIELD(Eigen::Vector2d, measured_cop, "m") = Eigen::Vector2d::Zero();
  STRIDE_FIELD(GroundOrigin, origin) = GroundOrigin::between_feet;

  static constexpr std::string_view kTypeName = "ComState";
};

// The robot's own numbers for the Ch. 7 models (mass and HAT from the URDF, CoM height from
// kinematics, sole from nao_dimensions.hpp); torques and gains stay with the strategy modules.
struct BalanceModel {
  STRIDE_FIELDS(BalanceModel);
  STRIDE_FIELD(bool, valid) = false;
  STRIDE_FIELD(double, mass, "kg") = 0;  // whole robot, kg
  // what the ankle torque carries (feet excluded), kg
  STRIDE_FIELD(double, mass_above_ankles, "kg") = 0;
  STRIDE_FIELD(double, com_height, "m") = 0;  // z_cm, m
  // I = m_HAT d^2 about the hip axis (Sec. 7.5.1), kg m^2
  STRIDE_FIELD(double, hat_inertia, "kg*m^2") = 0;
  STRIDE_FIELD(double, hat_mass, "kg") = 0;  // m_HAT: everything above the hips, kg
  // sole's back and front border in the ground frame, m
  STRIDE_FIELD(double, zmp_min, "m") = 0;
  STRIDE_FIELD(double, zmp_max, "m") = 0;
  // hip ROM from the standing posture
  STRIDE_FIELD(double, theta_max_forward, "rad") = 0;
  STRIDE_FIELD(double, theta_max_backward, "rad") = 0;

  static constexpr std::string_view kTypeName = "BalanceModel";
};

// The model as the analytic Ch. 7 code takes it; torques are the hip's forward / backward limits.
balance::BalanceParams balance_params(const BalanceModel& m, double tau_forward,
                                      double tau_backward);

}  // namespace stride
