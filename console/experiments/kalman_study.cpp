#include "console/experiments/kalman_study.hpp"

#include <cmath>
#include <limits>

#include "behaviours/posture/gyro_calibration.hpp"
#include "behaviours/posture/torso_kalman_filter.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {

KalmanSeries kalman_series(const WalkRecording& r, double gyro_alpha, bool start_at_first_sample) {
  KalmanSeries s;
  s.period = r.period;
  behaviours::GyroCalibrator gyro;  // GyroCalibration's own steps, replayed
  for (const console::WalkFrame& f : r.frames) {
    const Eigen::Vector2d rate = gyro.calibrate(Eigen::Vector2d(f.gyro_roll, f.gyro_pitch),
                                                gyro_alpha, start_at_first_sample);
    s.y.push_back(behaviours::torso_measurement(Eigen::Vector2d(f.imu_roll, f.imu_pitch), rate));
    s.truth.push_back({f.true_pitch, f.true_roll});
    s.truth_rate.push_back({f.true_pitch_rate, f.true_roll_rate});
  }
  return s;
}

std::vector<Eigen::Vector4d> filter_series(const KalmanSeries& s, const Eigen::Vector4d& q,
                                           const Eigen::Vector4d& r, double initial_variance) {
  behaviours::TorsoEstimator estimator;  // TorsoStateEstimator's own steps, replayed
  std::vector<Eigen::Vector4d> out;
  out.reserve(s.y.size());
  for (const Eigen::Vector4d& y : s.y) {
    estimator.step(s.period, q, r, initial_variance, y);
    out.push_back(estimator.filter.x);
  }
  return out;
}

EstimateScore score_estimate(const std::vector<Eigen::Vector2d>& estimate,
                             const std::vector<Eigen::Vector2d>& truth, double period,
                             std::size_t first, double max_lag) {
  if (estimate.size() != truth.size())
    throw Error("score_estimate: " + std::to_string(estimate.size()) + " estimates for " +
                std::to_string(truth.size()) + " true samples");
  const std::size_t n = truth.size();
  // Mean square of est[k + d] - truth[k] for axis i over k >= first with k + d < n.
  auto ms = [&](int i, std::size_t d) {
    double sum = 0;
    std::size_t count = 0;
    for (std::size_t k = first; k + d < n; ++k, ++count)
      sum += std::pow(estimate[k + d][i] - truth[k][i], 2);
    return count ? sum / count : std::numeric_limits<double>::quiet_NaN();
  };
  EstimateScore s;
  s.rms_pitch = std::sqrt(ms(0, 0));
  s.rms_roll = std::sqrt(ms(1, 0));
  const std::size_t max_d = static_cast<std::size_t>(max_lag / period + 0.5);
  for (int i = 0; i < 2; ++i) {
    std::size_t best = 0;
    double best_ms = ms(i, 0);
    for (std::size_t d = 1; d <= max_d && first + d < n; ++d)
      if (const double v = ms(i, d); v < best_ms) best_ms = v, best = d;
    (i == 0 ? s.lag_pitch : s.lag_roll) = best * period;
  }
  return s;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  if (n == 0) return 0;
  double ma = 0, mb = 0;
  for (std::size_t k = 0; k < n; ++k) ma += a[k], mb += b[k];
  ma /= n, mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t k = 0; k < n; ++k) {
    sab += (a[k] - ma) * (b[k] - mb);
    saa += (a[k] - ma) * (a[k] - ma);
    sbb += (b[k] - mb) * (b[k] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0;
}

}  // namespace stride::experiments
