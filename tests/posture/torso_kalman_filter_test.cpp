// Sec. 4.3.2: the torso Kalman filter (Eqs. 4.5-4.7, five steps) on seeded synthetic data.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/LU>

#include "behaviours/posture/posture_modules.hpp"
#include "behaviours/posture/torso_kalman_filter.hpp"

namespace stride::behaviours {
namespace {

constexpr double kPeriod = 0.01;

struct Rms {
  Eigen::Vector4d estimate = Eigen::Vector4d::Zero();
  Eigen::Vector4d measurement = Eigen::Vector4d::Zero();
};

// Truth x(t) from `truth`, measurement = truth + N(0, noise_sd); RMS over frames >= skip.
template <class Truth>
Rms run_filter(const Truth& truth, const Eigen::Vector4d& q, const Eigen::Vector4d& r,
               const Eigen::Vector4d& noise_sd, int frames, int skip, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  TorsoKalmanFilter f = initial_torso_filter(1000);
  const TorsoMatrix a = torso_transition(kPeriod);
  Rms rms;
  for (int k = 0; k < frames; ++k) {
    const Eigen::Vector4d x = truth(k * kPeriod);
    Eigen::Vector4d y = x;
    for (int i = 0; i < 4; ++i) y[i] += noise_sd[i] * normal(rng);
    torso_kalman_step(f, a, q, r, y);
    if (k < skip) continue;
    rms.estimate += (f.x - x).cwiseAbs2();
    rms.measurement += (y - x).cwiseAbs2();
  }
  rms.estimate = (rms.estimate / (frames - skip)).cwiseSqrt();
  rms.measurement = (rms.measurement / (frames - skip)).cwiseSqrt();
  return rms;
}

// Torso turning at a constant rate about both axes.
Eigen::Vector4d constant_rate(double t) {
  return {0.02 + 0.1 * t, -0.01 - 0.05 * t, 0.1, -0.05};
}

TEST(TorsoKalmanFilter, TransitionAndFirstStepFollowTheThesis) {
  const TorsoMatrix a = torso_transition(0.01);
  TorsoMatrix expected = TorsoMatrix::Identity();
  expected(0, 2) = expected(1, 3) = 0.01;  // Eq. 4.6
  EXPECT_EQ(a, expected);
  // With P0 = 1000 I the first update nearly takes the measurement (gain 1000/(1000+r)).
  TorsoKalmanFilter f = initial_torso_filter(1000);
  const TorsoVector q(1e-1, 1e-1, 1e-5, 1e-5), r(1e-4, 1e-4, 1e-3, 1e-3);
  const TorsoVector y(0.1, -0.2, 0.3, -0.4);
  torso_kalman_step(f, a, q, r, y);
  // Closed form for one axis: P- = [[1000 + 1000 T^2 + q0, 1000 T], [1000 T, 1000 + q2]].
  const double p00 = 1000 + 1000 * 1e-4 + 1e-1, p02 = 10, p22 = 1000 + 1e-5;
  Eigen::Matrix2d prior;
  prior << p00, p02, p02, p22;
  const Eigen::Matrix2d k =
      prior * (prior + Eigen::Vector2d(1e-4, 1e-3).asDiagonal().toDenseMatrix()).inverse();
  EXPECT_NEAR(f.gain(0, 0), k(0, 0), 1e-12);
  EXPECT_NEAR(f.gain(0, 2), k(0, 1), 1e-12);
  EXPECT_NEAR(f.x[0], k(0, 0) * 0.1 + k(0, 1) * 0.3, 1e-12);
  EXPECT_NEAR(f.x[2], k(1, 0) * 0.1 + k(1, 1) * 0.3, 1e-12);
  EXPECT_EQ(f.gain(0, 1), 0);  // the axes stay decoupled
}

TEST(TorsoKalmanFilter, EstimateIsCloserToTheTruthThanTheMeasurement) {
  // Measurement noise matching R; small Q because the truth follows the model exactly.
  const Eigen::Vector4d r(1e-4, 1e-4, 1e-3, 1e-3);
  const Eigen::Vector4d q = Eigen::Vector4d::Constant(1e-8);
  const Rms rms = run_filter(constant_rate, q, r, r.cwiseSqrt(), 3000, 200, 7);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(rms.measurement[i], std::sqrt(r[i]), 0.05 * std::sqrt(r[i])) << i;
    EXPECT_LT(rms.estimate[i], 0.3 * rms.measurement[i]) << i;
  }
  // The thesis' own Q trusts the angle measurement (Q >> R there) but smooths the rates.
  const TorsoStateEstimatorParameters thesis;
  const Rms t =
      run_filter(constant_rate, thesis.q_diagonal, thesis.r_diagonal, r.cwiseSqrt(), 3000, 200, 7);
  EXPECT_LT(t.estimate[0], t.measurement[0]);
  EXPECT_LT(t.estimate[2], 0.5 * t.measurement[2]);
  EXPECT_LT(t.estimate[3], 0.5 * t.measurement[3]);
}

// Steady-state a priori covariance of the filter by the structure-preserving doubling
// algorithm: an independent solution of the discrete algebraic Riccati equation.
TorsoMatrix riccati_by_doubling(const TorsoMatrix& a, const TorsoMatrix& q, const TorsoMatrix& r) {
  TorsoMatrix ak = a.transpose(), g = r.inverse(), h = q;
  const TorsoMatrix i = TorsoMatrix::Identity();
  for (int n = 0; n < 60; ++n) {
    const TorsoMatrix w = (i + g * h).inverse();
    const TorsoMatrix a1 = ak * w * ak;
    const TorsoMatrix g1 = g + ak * w * g * ak.transpose();
    const TorsoMatrix h1 = h + ak.transpose() * h * w * ak;
    ak = a1;
    g = g1;
    h = h1;
  }
  return h;
}

TEST(TorsoKalmanFilter, SteadyStateGainSolvesTheRiccatiEquation) {
  const TorsoStateEstimatorParameters p;  // thesis Q and R
  const TorsoMatrix a = torso_transition(kPeriod);
  const TorsoMatrix q = p.q_diagonal.asDiagonal(), r = p.r_diagonal.asDiagonal();
  TorsoKalmanFilter f = initial_torso_filter(p.initial_variance);
  for (int k = 0; k < 20000; ++k)
    torso_kalman_step(f, a, p.q_diagonal, p.r_diagonal, TorsoVector::Zero());
  const TorsoMatrix prior = a * f.p * a.transpose() + q;
  const TorsoMatrix x = riccati_by_doubling(a, q, r);
  // x solves X = A (X - X (X + R)^-1 X) A^T + Q.
  const TorsoMatrix residual = a * (x - x * (x + r).inverse() * x) * a.transpose() + q - x;
  EXPECT_LT(residual.cwiseAbs().maxCoeff(), 1e-12);
  const TorsoMatrix k_riccati = x * (x + r).inverse();
  EXPECT_LT((f.gain - k_riccati).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((prior - x).cwiseAbs().maxCoeff(), 1e-9 * x.cwiseAbs().maxCoeff());
  // Numbers to compare with the thesis' choice: angle gain near 1, rate gain small.
  EXPECT_GT(k_riccati(0, 0), 0.99);
  EXPECT_LT(k_riccati(2, 2), 0.2);
}

// Figs. 4.1-4.2: more process noise Q (R fixed) or less measurement noise R (Q fixed) makes the
// estimate follow the torso with less lag but passes more noise.
struct Tradeoff {
  double lag_error;  // RMS pitch error on a noise-free 2 Hz sway (model mismatch only)
  double noise_rms;  // RMS pitch-rate estimate on pure noise (truth 0)
};

Tradeoff tradeoff(const Eigen::Vector4d& q, const Eigen::Vector4d& r) {
  const double w = 2 * std::numbers::pi / 0.5;  // walking period of Table 4.2
  const auto sway = [w](double t) {
    return Eigen::Vector4d(0.05 * std::sin(w * t), 0.03 * std::sin(w * t),
                           0.05 * w * std::cos(w * t), 0.03 * w * std::cos(w * t));
  };
  const auto still = [](double) { return Eigen::Vector4d::Zero(); };
  const Eigen::Vector4d noise(0.01, 0.01, 0.03, 0.03);
  return {run_filter(sway, q, r, Eigen::Vector4d::Zero(), 1000, 200, 1).estimate[0],
          run_filter(still, q, r, noise, 3000, 200, 3).estimate[2]};
}

TEST(TorsoKalmanFilter, CovariancesTradeLagAgainstNoiseAsInFigures41And42) {
  const Eigen::Vector4d thesis_q(1e-1, 1e-1, 1e-5, 1e-5);
  const Eigen::Vector4d fig41_r = Eigen::Vector4d::Constant(1e-3);
  Tradeoff previous{1e9, 0};
  for (const double scale : {1e-2, 1.0, 1e2}) {  // Fig. 4.1: Q grows, R fixed
    const Tradeoff t = tradeoff(scale * thesis_q, fig41_r);
    EXPECT_LT(t.lag_error, previous.lag_error) << scale;
    EXPECT_GT(t.noise_rms, previous.noise_rms) << scale;
    previous = t;
  }
  previous = {1e9, 0};
  for (const double scale : {1e1, 1.0, 1e-1}) {  // Fig. 4.2: R shrinks, Q fixed
    const Tradeoff t = tradeoff(thesis_q, scale * Eigen::Vector4d(1e-4, 1e-4, 1e-3, 1e-3));
    EXPECT_LT(t.lag_error, previous.lag_error) << scale;
    EXPECT_GT(t.noise_rms, previous.noise_rms) << scale;
    previous = t;
  }
}

}  // namespace
}  // namespace stride::behaviours
