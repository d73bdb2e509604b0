// Scoring of torso estimates: a pure delay is found as the lag and gives the closed-form RMS of
// two shifted sines; the offline filter tracks a clean constant-rate signal; correlation signs.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "console/experiments/kalman_study.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(KalmanStudy, DelayedSineScoresItsDelayAndClosedFormRms) {
  const double dt = 0.01, f = 2.0, amp = 0.1;  // 2 Hz, 0.1 rad
  const int delay = 5;
  std::vector<Eigen::Vector2d> truth, est;
  for (int k = 0; k < 1000; ++k) {
    const double t = k * dt;
    truth.push_back({amp * std::sin(2 * kPi * f * t), 0.5 * amp * std::cos(2 * kPi * f * t)});
    const double td = t - delay * dt;
    est.push_back({amp * std::sin(2 * kPi * f * td), 0.5 * amp * std::cos(2 * kPi * f * td)});
  }
  const EstimateScore s = score_estimate(est, truth, dt, 0);
  EXPECT_NEAR(s.lag_pitch, delay * dt, 1e-12);
  EXPECT_NEAR(s.lag_roll, delay * dt, 1e-12);
  // sin(a) - sin(a - d) has amplitude 2 sin(d / 2); RMS over whole periods = that / sqrt(2).
  const double expected = amp * 2 * std::sin(2 * kPi * f * delay * dt / 2) / std::sqrt(2.0);
  EXPECT_NEAR(s.rms_pitch, expected, 1e-3 * expected);
  EXPECT_NEAR(s.rms_roll, 0.5 * expected, 1e-3 * expected);
}

TEST(KalmanStudy, FilterFollowsANoiseFreeConstantRateAndMismatchedSizesAreAnError) {
  KalmanSeries s;
  s.period = 0.01;
  for (int k = 0; k < 300; ++k) {
    const double t = k * s.period;
    s.y.push_back({0.2 * t, -0.1 * t, 0.2, -0.1});
    s.truth.push_back({0.2 * t, -0.1 * t});
  }
  const auto x = filter_series(s, {1e-1, 1e-1, 1e-5, 1e-5}, {1e-4, 1e-4, 1e-3, 1e-3}, 1000);
  EXPECT_NEAR(x.back()[0], 0.2 * 2.99, 1e-6);
  EXPECT_NEAR(x.back()[3], -0.1, 1e-6);
  std::vector<Eigen::Vector2d> shorter(s.truth.begin(), s.truth.end() - 1);
  EXPECT_THROW(score_estimate(shorter, s.truth, 0.01, 0), Error);
}

TEST(KalmanStudy, GyroOffsetStartsAtTheFirstSampleOrAtZero) {
  WalkRecording r;
  r.period = 0.01;
  for (int k = 0; k < 100; ++k) {
    console::WalkFrame f;
    f.gyro_pitch = -0.314;  // the thesis' -18 deg/s, torso still
    f.gyro_roll = 0.02;
    r.frames.push_back(f);
  }
  const KalmanSeries settled = kalman_series(r);
  const KalmanSeries from_zero = kalman_series(r, 0.001, false);
  ASSERT_EQ(settled.y.size(), 100u);
  for (int k : {0, 99}) {
    EXPECT_NEAR(settled.y[k][2], 0, 1e-15) << k;
    EXPECT_NEAR(settled.y[k][3], 0, 1e-15) << k;
    EXPECT_NEAR(from_zero.y[k][2], -0.314 * std::pow(0.999, k + 1), 1e-12) << k;  // Eqs. 4.2, 4.4
    EXPECT_NEAR(from_zero.y[k][3], 0.02 * std::pow(0.999, k + 1), 1e-12) << k;
  }
  EXPECT_EQ(settled.truth_rate.size(), 100u);
}

TEST(KalmanStudy, CorrelationOfASeriesWithItselfAndItsNegation) {
  const std::vector<double> a{1, 3, 2, 5, 4}, b{-1, -3, -2, -5, -4}, c{2, 2, 2, 2, 2};
  EXPECT_NEAR(correlation(a, a), 1.0, 1e-12);
  EXPECT_NEAR(correlation(a, b), -1.0, 1e-12);
  EXPECT_EQ(correlation(a, c), 0.0);
}

}  // namespace
}  // namespace stride::experiments
