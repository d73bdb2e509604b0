#include "behaviours/posture/torso_kalman_filter.hpp"

#include <Eigen/LU>

namespace stride::behaviours {

TorsoKalmanFilter initial_torso_filter(double initial_variance) {
  TorsoKalmanFilter f;
  f.p = initial_variance * TorsoMatrix::Identity();
  return f;
}

TorsoMatrix torso_transition(double period) {
  TorsoMatrix a = TorsoMatrix::Identity();  // Eq. 4.6
  a(0, 2) = period;
  a(1, 3) = period;
  return a;
}

void torso_kalman_step(TorsoKalmanFilter& f, const TorsoMatrix& a, const TorsoVector& q_diagonal,
                       const TorsoVector& r_diagonal, const TorsoVector& y) {
  // C = I in the measurement model y_k = C x_k, so C drops out of steps 3-5.
  const TorsoVector x_prior = a * f.x;  // Eq. 4.5 with u_k = 0: step 1
  const TorsoMatrix p_prior = a * f.p * a.transpose() + TorsoMatrix(q_diagonal.asDiagonal());  // 2
  const TorsoMatrix s = p_prior + TorsoMatrix(r_diagonal.asDiagonal());
  f.gain = p_prior * s.inverse();                      // step 3
  f.x = x_prior + f.gain * (y - x_prior);              // Eq. 4.7 in y - C x: step 4
  f.p = (TorsoMatrix::Identity() - f.gain) * p_prior;  // step 5
}

TorsoVector torso_measurement(const Eigen::Vector2d& angles, const Eigen::Vector2d& rates) {
  return TorsoVector(angles.y(), angles.x(), rates.y(), rates.x());
}

void TorsoEstimator::step(double period, const TorsoVector& q_diagonal,
                          const TorsoVector& r_diagonal, double initial_variance,
                          const TorsoVector& y) {
  if (!started) filter = initial_torso_filter(initial_variance);
  started = true;
  torso_kalman_step(filter, torso_transition(period), q_diagonal, r_diagonal, y);
}

}  // namespace stride::behaviours
