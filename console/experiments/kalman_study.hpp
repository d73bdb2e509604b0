#pragma once
// The torso Kalman filter (thesis Sec. 4.3.2) rerun offline on a recorded walk: the same IMU
// inputs through filters with other Q and R (Figs. 4.1-4.2), scored against the simulator's
// ground-truth torso pitch/roll by RMS error and lag.
#include <vector>

#include <Eigen/Core>

#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

// Measurements y_k = [pitch, roll, pitch_rate, roll_rate] (Eq. 4.7) and the true angles.
struct KalmanSeries {
  std::vector<Eigen::Vector4d> y;
  std::vector<Eigen::Vector2d> truth;       // pitch, roll
  std::vector<Eigen::Vector2d> truth_rate;  // pitch rate, roll rate
  double period = 0.01;
};

// From a trace: IMU angles, gyro rates with the running offset (Eq. 4.1, Eq. 4.2; alpha) removed;
// the offset starts at the first sample or at 0, as GyroCalibration's start_at_first_sample.
KalmanSeries kalman_series(const WalkRecording& r, double gyro_alpha = 0.001,
                           bool start_at_first_sample = true);

// The filter of Sec. 4.3.2 over the whole series; returns x_{k|k} for every k.
std::vector<Eigen::Vector4d> filter_series(const KalmanSeries& s, const Eigen::Vector4d& q,
                                           const Eigen::Vector4d& r, double initial_variance);

struct EstimateScore {
  double rms_pitch = 0, rms_roll = 0;  // rad
  double lag_pitch = 0, lag_roll = 0;  // s, shift that best aligns the estimate with the truth
};

// RMS of estimate - truth and the delay d in [0, max_lag] minimising RMS(est[k + d] - truth[k]),
// over samples from `first` on. Sizes must match (throws stride::Error otherwise).
EstimateScore score_estimate(const std::vector<Eigen::Vector2d>& estimate,
                             const std::vector<Eigen::Vector2d>& truth, double period,
                             std::size_t first, double max_lag = 0.3);

// Pearson correlation of two equally long series (0 if either is constant).
double correlation(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace stride::experiments
