#pragma once
// Kalman filter of the torso orientation and rate (thesis Sec. 4.3.2): constant-rate model per
// axis, every state measured (C = I: IMU angles and calibrated gyro rates), no control input.
#include <Eigen/Core>

namespace stride::behaviours {

// State of Eq. 4.5: [pitch, roll, pitch_rate, roll_rate].
using TorsoVector = Eigen::Vector4d;
using TorsoMatrix = Eigen::Matrix4d;

struct TorsoKalmanFilter {
  TorsoVector x = TorsoVector::Zero();  // x_{k|k}, starts at 0 as in the thesis
  TorsoMatrix p = TorsoMatrix::Identity();
  TorsoMatrix gain = TorsoMatrix::Zero();  // K_k of the last update
};

// P_{0|0} = L * I; the thesis uses L = 1000 because the starting posture is uncertain.
TorsoKalmanFilter initial_torso_filter(double initial_variance);

// Angles integrate the rates over one period T (Eq. 4.6).
TorsoMatrix torso_transition(double period);

// One predict/update cycle (the thesis' five steps) with diagonal Q and R and measurement y.
void torso_kalman_step(TorsoKalmanFilter& f, const TorsoMatrix& a, const TorsoVector& q_diagonal,
                       const TorsoVector& r_diagonal, const TorsoVector& y);

// Measurement y_k = x_k + v (Eq. 4.7, C = I) from the IMU's angles and the calibrated gyro
// rates, both ordered (roll, pitch) as the sensors give them; the state puts pitch first.
TorsoVector torso_measurement(const Eigen::Vector2d& angles, const Eigen::Vector2d& rates);

// The filter run frame by frame, as TorsoStateEstimator runs it and an offline replay reruns it:
// P_{0|0} = L * I at the first frame, then one predict/update cycle per frame.
struct TorsoEstimator {
  TorsoKalmanFilter filter;
  bool started = false;
  void step(double period, const TorsoVector& q_diagonal, const TorsoVector& r_diagonal,
            double initial_variance, const TorsoVector& y);
};

}  // namespace stride::behaviours
