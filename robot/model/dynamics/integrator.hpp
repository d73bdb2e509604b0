#pragma once
// Classical fourth-order Runge-Kutta step for second-order systems qdd = f(q, qd).
#include <Eigen/Core>

namespace stride::model {

template <int N, typename Accel>
void rk4_step(Eigen::Matrix<double, N, 1>& q, Eigen::Matrix<double, N, 1>& qd, double dt,
              const Accel& acceleration) {
  using V = Eigen::Matrix<double, N, 1>;
  const V a1 = acceleration(q, qd);
  const V q2 = q + 0.5 * dt * qd, v2 = qd + 0.5 * dt * a1;
  const V a2 = acceleration(q2, v2);
  const V q3 = q + 0.5 * dt * v2, v3 = qd + 0.5 * dt * a2;
  const V a3 = acceleration(q3, v3);
  const V q4 = q + dt * v3, v4 = qd + dt * a3;
  const V a4 = acceleration(q4, v4);
  q += dt / 6 * (qd + 2 * v2 + 2 * v3 + v4);
  qd += dt / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
}

}  // namespace stride::model
