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
  bool valid = false;  // false until the filter has seen joints and a centre of pressure
  double x = 0, xdot = 0, y = 0, ydot = 0;  // filtered CoM state (Sec. 7.2)
  double zmp_x = 0, zmp_y = 0;              // filtered ZMP
  double com_height = 0;                    // kinematic CoM height z0 above the soles
  Eigen::Vector3d measured_com = Eigen::Vector3d::Zero();  // kinematic CoM, this frame
  Eigen::Vector2d measured_cop = Eigen::Vector2d::Zero();  // FSR centre of pressure, this frame
  GroundOrigin origin = GroundOrigin::between_feet;

  static constexpr std::string_view kTypeName = "ComState";
  static constexpr auto fields() {
    using S = ComState;
    return std::make_tuple(
        field("valid", &S::valid), field("x", &S::x, "m"), field("xdot", &S::xdot, "m/s"),
        field("y", &S::y, "m"), field("ydot", &S::ydot, "m/s"), field("zmp_x", &S::zmp_x, "m"),
        field("zmp_y", &S::zmp_y, "m"), field("com_height", &S::com_height, "m"),
        field("measured_com", &S::measured_com, "m"), field("measured_cop", &S::measured_cop, "m"),
        field("origin", &S::origin));
  }
};

// The robot's own numbers for the Ch. 7 models (mass and HAT from the URDF, CoM height from
// kinematics, sole from nao_dimensions.hpp); torques and gains stay with the strategy modules.
struct BalanceModel {
  bool valid = false;
  double mass = 0;                  // whole robot, kg
  double mass_above_ankles = 0;     // what the ankle torque carries (feet excluded), kg
  double com_height = 0;            // z_cm, m
  double hat_inertia = 0;           // I = m_HAT d^2 about the hip axis (Sec. 7.5.1), kg m^2
  double hat_mass = 0;              // m_HAT: everything above the hips, kg
  double zmp_min = 0, zmp_max = 0;  // sole's back and front border in the ground frame, m
  double theta_max_forward = 0, theta_max_backward = 0;  // hip ROM from the standing posture

  static constexpr std::string_view kTypeName = "BalanceModel";
  static constexpr auto fields() {
    using B = BalanceModel;
    return std::make_tuple(field("valid", &B::valid), field("mass", &B::mass, "kg"),
                           field("mass_above_ankles", &B::mass_above_ankles, "kg"),
                           field("com_height", &B::com_height, "m"),
                           field("hat_inertia", &B::hat_inertia, "kg*m^2"),
                           field("hat_mass", &B::hat_mass, "kg"),
                           field("zmp_min", &B::zmp_min, "m"), field("zmp_max", &B::zmp_max, "m"),
                           field("theta_max_forward", &B::theta_max_forward, "rad"),
                           field("theta_max_backward", &B::theta_max_backward, "rad"));
  }
};

// The model as the analytic Ch. 7 code takes it; torques are the hip's forward / backward limits.
balance::BalanceParams balance_params(const BalanceModel& m, double tau_forward,
                                      double tau_backward);

}  // namespace stride
