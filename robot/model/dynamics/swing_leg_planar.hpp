#pragma once
// Planar three-link swing leg (thesis App. C, Fig. C.1): thigh, tibia, foot in the sagittal
// plane. q = [hip, knee, ankle] pitch, q1 measured from the vertical.
// H q'' + C q' + g = tau (Eq. C.15) with C chosen by Eq. C.14, and the regressor Y of Eq. 5.4 with
// a = [J1 .. J6, G1 .. G3].
#include <Eigen/Core>

namespace stride::model {

using Vector9d = Eigen::Matrix<double, 9, 1>;
using PlanarRegressor = Eigen::Matrix<double, 3, 9>;

struct PlanarLegData {
  double m1, m2, m3;  // kg: thigh, tibia, foot
  double i1, i2, i3;  // kg m^2 about each link's CoM, pitch axis
  double l1, l2, l3;  // m: thigh, tibia, foot height
  double b1, b2, b3;  // m: joint to link CoM
  double gravity = 9.81;
};

// The left-leg values of Sec. 5.4.1.1.
PlanarLegData thesis_planar_leg();

// The inertial groups J1..J6 and G1..G3 (App. C).
Vector9d planar_parameters(const PlanarLegData& d);

Eigen::Matrix3d planar_inertia(const Eigen::Vector3d& q, const Vector9d& a);
Eigen::Matrix3d planar_coriolis(const Eigen::Vector3d& q, const Eigen::Vector3d& qd,
                                const Vector9d& a);  // C by the choice of Eq. C.14
Eigen::Vector3d planar_gravity(const Eigen::Vector3d& q, const Vector9d& a);

// Y(q, q', q'_r, q''_r) a = H q''_r + C q'_r + g (the regressor of Eq. 5.4).
PlanarRegressor planar_regressor(const Eigen::Vector3d& q, const Eigen::Vector3d& qd,
                                 const Eigen::Vector3d& qd_r, const Eigen::Vector3d& qdd_r);

// q'' = H^-1 (tau - C q' - g).
Eigen::Vector3d planar_forward_dynamics(const Eigen::Vector3d& q, const Eigen::Vector3d& qd,
                                        const Eigen::Vector3d& tau, const Vector9d& a);

// Kinetic plus potential energy (K and P of App. C).
double planar_energy(const Eigen::Vector3d& q, const Eigen::Vector3d& qd, const Vector9d& a);

}  // namespace stride::model
