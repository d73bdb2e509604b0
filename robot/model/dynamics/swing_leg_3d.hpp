#pragma once
// Three-dimensional five-joint swing leg (thesis App. C, Fig. C.2): q = [hip roll a1, hip pitch
// t1, knee t2, ankle pitch t3, ankle roll a2] (Eq. C.24's ordering), link CoMs of Eq. C.16, Eq.
// C.18, Eq. C.20, kinetic energy Eq. C.22, potential Eq. C.23. H, C (Eq. C.14 choice), g and the
// 5x17 regressor Y with a = [J1 .. J17] are computed from the model's geometry, linear in a by
// construction.
#include <Eigen/Core>

namespace stride::model {

using Vector5d = Eigen::Matrix<double, 5, 1>;
using Matrix5d = Eigen::Matrix<double, 5, 5>;
using Vector17d = Eigen::Matrix<double, 17, 1>;
using Leg3dRegressor = Eigen::Matrix<double, 5, 17>;

struct Leg3dData {
  double m1, m2, m3;
  double ixx1, ixx2, ixx3;  // roll inertias about the CoMs
  double iyy1, iyy2, iyy3;  // pitch inertias about the CoMs
  double l1, l2, l3;
  double b1, b2, b3;
  double gravity = 9.81;
};

// The left-leg values of Sec. 5.4.1.2.
Leg3dData thesis_3d_leg();

// The 17 inertial groups J1..J17 of App. C.
Vector17d leg3d_parameters(const Leg3dData& d);

struct Leg3dTerms {
  Matrix5d inertia;   // H
  Matrix5d coriolis;  // C, Eq. C.14
  Vector5d gravity;   // g
};

Leg3dTerms leg3d_terms(const Vector5d& q, const Vector5d& qd, const Vector17d& a);

// Y(q, q', q'_r, q''_r) a = H q''_r + C q'_r + g.
Leg3dRegressor leg3d_regressor(const Vector5d& q, const Vector5d& qd, const Vector5d& qd_r,
                               const Vector5d& qdd_r);

// C q' alone (Coriolis and centrifugal torques), much cheaper than the full matrix C.
Vector5d leg3d_coriolis_times_velocity(const Vector5d& q, const Vector5d& qd, const Vector17d& a);

Vector5d leg3d_forward_dynamics(const Vector5d& q, const Vector5d& qd, const Vector5d& tau,
                                const Vector17d& a);

double leg3d_energy(const Vector5d& q, const Vector5d& qd, const Vector17d& a);

}  // namespace stride::model
