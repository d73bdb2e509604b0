#include "robot/model/dynamics/swing_leg_planar.hpp"

#include <cmath>

#include <Eigen/Cholesky>

#include <Eigen/Cholesky>

namespace stride::model {

PlanarLegData thesis_planar_leg() {
  return {0.3897, 0.2914, 0.1618,  0.00159107278, 0.00112865226, 0.00064434250,
          0.1,    0.1029, 0.04519, 0.05373,       0.04936,       0.03239};
}

Vector9d planar_parameters(const PlanarLegData& d) {
  Vector9d a;
  a << d.m1 * d.b1 * d.b1 + d.i1 + d.m2 * d.l1 * d.l1 + d.m3 * d.l1 * d.l1,  // J1
      d.m2 * d.l1 * d.b2 + d.m3 * d.l1 * d.l2,                               // J2
      d.m2 * d.b2 * d.b2 + d.i2 + d.m3 * d.l2 * d.l2,                        // J3
      d.m3 * d.l2 * d.b3,                                                    // J4
      d.m3 * d.b3 * d.b3 + d.i3,                                             // J5
      d.m3 * d.l1 * d.b3,                                                    // J6
      (d.m1 * d.b1 + d.m2 * d.l1 + d.m3 * d.l1) * d.gravity,                 // G1
      (d.m2 * d.b2 + d.m3 * d.l2) * d.gravity,                               // G2
      d.m3 * d.b3 * d.gravity;                                               // G3
  return a;
}

Eigen::Matrix3d planar_inertia(const Eigen::Vector3d& q, const Vector9d& a) {
  const double c2 = std::cos(q[1]), c3 = std::cos(q[2]), c23 = std::cos(q[1] + q[2]);
  Eigen::Matrix3d h;
  h(0, 0) = a[0] + 2 * a[1] * c2 + a[2] + 2 * a[3] * c3 + a[4] + 2 * a[5] * c23;
  h(0, 1) = a[1] * c2 + a[2] + 2 * a[3] * c3 + a[4] + a[5] * c23;
  h(0, 2) = a[3] * c3 + a[4] + a[5] * c23;
  h(1, 1) = a[2] + 2 * a[3] * c3 + a[4];
  h(1, 2) = a[3] * c3 + a[4];
  h(2, 2) = a[4];
  h(1, 0) = h(0, 1);
  h(2, 0) = h(0, 2);
  h(2, 1) = h(1, 2);
  return h;
}

Eigen::Matrix3d planar_coriolis(const Eigen::Vector3d& q, const Eigen::Vector3d& qd,
                                const Vector9d& a) {
  const double s2 = std::sin(q[1]), s3 = std::sin(q[2]), s23 = std::sin(q[1] + q[2]);
  const double p = a[1] * s2 + a[5] * s23;  // J2 s2 + J6 s23
  const double r = a[3] * s3 + a[5] * s23;  // J4 s3 + J6 s23
  const double k = a[3] * s3;               // J4 s3
  const double sum = qd[0] + qd[1] + qd[2];
  Eigen::Matrix3d c;  // Eq. C.14, the thesis' C_ij written out
  c << -p * qd[1] - r * qd[2], -p * qd[0] - p * qd[1] - r * qd[2], -r * sum,  //
      p * qd[0] - k * qd[2], -k * qd[2], -k * sum,                            //
      r * qd[0] + k * qd[1], k * (qd[0] + qd[1]), 0;
  return c;
}

Eigen::Vector3d planar_gravity(const Eigen::Vector3d& q, const Vector9d& a) {
  const double s1 = std::sin(q[0]), s12 = std::sin(q[0] + q[1]), s123 = std::sin(q.sum());
  return {a[6] * s1 + a[7] * s12 + a[8] * s123, a[7] * s12 + a[8] * s123, a[8] * s123};
}

PlanarRegressor planar_regressor(const Eigen::Vector3d& q, const Eigen::Vector3d& qd,
                                 const Eigen::Vector3d& qd_r, const Eigen::Vector3d& qdd_r) {
  const double c2 = std::cos(q[1]), s2 = std::sin(q[1]), c3 = std::cos(q[2]), s3 = std::sin(q[2]),
               c23 = std::cos(q[1] + q[2]), s23 = std::sin(q[1] + q[2]);
  const double s1 = std::sin(q[0]), s12 = std::sin(q[0] + q[1]), s123 = std::sin(q.sum());
  const double qsum = qd.sum();
  PlanarRegressor y = PlanarRegressor::Zero();  // Eq. 5.4, Y_ij of Appendix C
  // Row 1
  y(0, 0) = qdd_r[0];
  y(0, 1) =
      c2 * (2 * qdd_r[0] + qdd_r[1]) - s2 * (qd[1] * qd_r[0] + qd[0] * qd_r[1] + qd[1] * qd_r[1]);
  y(0, 2) = qdd_r[0] + qdd_r[1];
  y(0, 3) = c3 * (2 * qdd_r[0] + 2 * qdd_r[1] + qdd_r[2]) - s3 * qd[2] * (qd_r[0] + qd_r[1]) -
            s3 * qsum * qd_r[2];
  y(0, 4) = qdd_r.sum();
  y(0, 5) = c23 * (2 * qdd_r[0] + qdd_r[1] + qdd_r[2]) - s23 * (qd[1] + qd[2]) * qd_r[0] -
            s23 * qsum * (qd_r[1] + qd_r[2]);
  y(0, 6) = s1;
  y(0, 7) = s12;
  y(0, 8) = s123;
  // Row 2
  y(1, 1) = c2 * qdd_r[0] + s2 * qd[0] * qd_r[0];
  y(1, 2) = qdd_r[0] + qdd_r[1];
  y(1, 3) = c3 * (2 * qdd_r[0] + 2 * qdd_r[1] + qdd_r[2]) - s3 * qd[2] * (qd_r[0] + qd_r[1]) -
            s3 * qsum * qd_r[2];
  y(1, 4) = qdd_r.sum();
  y(1, 5) = c23 * qdd_r[0] + s23 * qd[0] * qd_r[0];
  y(1, 7) = s12;
  y(1, 8) = s123;
  // Row 3
  y(2, 3) = c3 * (qdd_r[0] + qdd_r[1]) + s3 * (qd[0] + qd[1]) * (qd_r[0] + qd_r[1]);
  y(2, 4) = qdd_r.sum();
  y(2, 5) = c23 * qdd_r[0] + s23 * qd[0] * qd_r[0];
  y(2, 8) = s123;
  return y;
}

Eigen::Vector3d planar_forward_dynamics(const Eigen::Vector3d& q, const Eigen::Vector3d& qd,
                                        const Eigen::Vector3d& tau, const Vector9d& a) {
  return planar_inertia(q, a).llt().solve(tau - planar_coriolis(q, qd, a) * qd -  // Eq. C.15
                                          planar_gravity(q, a));
}

double planar_energy(const Eigen::Vector3d& q, const Eigen::Vector3d& qd, const Vector9d& a) {
  const double potential =
      -a[6] * std::cos(q[0]) - a[7] * std::cos(q[0] + q[1]) - a[8] * std::cos(q.sum());
  return 0.5 * qd.dot(planar_inertia(q, a) * qd) + potential;
}

}  // namespace stride::model
