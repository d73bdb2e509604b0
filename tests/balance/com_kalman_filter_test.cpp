// 3D-LIPM Kalman filter for the CoM (Eqs. 7.1-7.4).
#include "behaviours/balance/com_kalman_filter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "robot/core/error.hpp"

namespace stride::balance {
namespace {

TEST(ComKalmanFilter, ModelMatchesEq73And74) {
  const double T = 0.01, w2 = 9.81 / 0.32;
  const ComFilterModel m = com_filter_model(0.32, 9.81, T, 1e-4, 1e-3, 1e-3);
  for (int o : {0, 3}) {
    EXPECT_DOUBLE_EQ(m.A(o, o + 1), T);
    EXPECT_NEAR(m.A(o + 1, o), w2 * T, 1e-12);
    EXPECT_NEAR(m.A(o + 1, o + 2), -w2 * T, 1e-12);
    EXPECT_DOUBLE_EQ(m.A(o + 2, o + 2), 1);
  }
  EXPECT_DOUBLE_EQ(m.A(0, 3), 0);  // the two axes are decoupled
  EXPECT_DOUBLE_EQ(m.B(2, 0), T);
  EXPECT_DOUBLE_EQ(m.B(5, 1), T);
  const auto C = com_cop_force_measurement(5.183, std::sqrt(w2));
  EXPECT_NEAR(C(2, 0), 5.183 * w2, 1e-9);
  EXPECT_NEAR(C(2, 2), -5.183 * w2, 1e-9);
}

// Simulates the true LIPM (fine RK4-free exact sub-steps), measures the kinematic CoM and the FSR
// CoP with noise, and checks that the filtered velocity beats differentiating the CoM.
TEST(ComKalmanFilter, EstimatesVelocityBetterThanFiniteDifferences) {
  const double z0 = 0.32, g = 9.81, T = 0.01, w = std::sqrt(g / z0);
  const double sigma_pos = 0.002, sigma_cop = 0.005;
  const ComFilterModel model = com_filter_model(z0, g, T, 1e-5, 2e-3, 2e-3);
  const Eigen::Matrix4d R = Eigen::Vector4d(sigma_pos * sigma_pos, sigma_cop * sigma_cop,
                                            sigma_pos * sigma_pos, sigma_cop * sigma_cop)
                                .asDiagonal();
  std::mt19937 rng(42);
  std::normal_distribution<double> pos_noise(0, sigma_pos), cop_noise(0, sigma_cop);

  // Truth: the ZMP sways sinusoidally under the CoM so the CoM stays bounded.
  double x = 0.0, v = 0.02, y = 0.0, vy = -0.01;
  ComEstimate est;
  est.P = 0.01 * ComFilterCovariance::Identity();
  double prev_meas_x = 0, sq_err_kf = 0, sq_err_fd = 0;
  int count = 0;
  for (int k = 0; k < 1000; ++k) {
    const double t = k * T;
    const double zmp_x = x + v / w * 0.5 + 0.01 * std::sin(2 * t);  // keeps x bounded
    const double zmp_y = y + vy / w * 0.5;
    for (int s = 0; s < 100; ++s) {  // true dynamics, Eq. 7.1, fine explicit steps
      const double h = T / 100;
      v += h * w * w * (x - zmp_x);
      x += h * v;
      vy += h * w * w * (y - zmp_y);
      y += h * vy;
    }
    est = predict(model, est, Eigen::Vector2d::Zero());
    const double mx = x + pos_noise(rng);
    Eigen::Vector4d meas(mx, zmp_x + cop_noise(rng), y + pos_noise(rng), zmp_y + cop_noise(rng));
    est = update(est, meas, com_cop_measurement(), R);
    if (k > 200) {
      sq_err_kf += std::pow(est.x(1) - v, 2);
      sq_err_fd += std::pow((mx - prev_meas_x) / T - v, 2);
      ++count;
    }
    prev_meas_x = mx;
  }
  const double rms_kf = std::sqrt(sq_err_kf / count), rms_fd = std::sqrt(sq_err_fd / count);
  EXPECT_LT(rms_kf, 0.2 * rms_fd) << "kf " << rms_kf << " fd " << rms_fd;
  EXPECT_LT(rms_kf, 0.05);
  EXPECT_LT((est.P - est.P.transpose()).norm(), 1e-12);
}

TEST(ComKalmanFilter, MismatchedMeasurementIsAnError) {
  ComEstimate e;
  EXPECT_THROW(
      update(e, Eigen::Vector3d::Zero(), com_cop_measurement(), Eigen::Matrix3d::Identity()),
      Error);
  EXPECT_THROW(com_filter_model(0, 9.81, 0.01, 1, 1, 1), Error);
  // Its matrices hold at most kMaxMeasurements rows in place (no allocation in a frame).
  const Eigen::MatrixXd C7 = Eigen::MatrixXd::Identity(kMaxMeasurements + 1, 6);
  EXPECT_THROW(update(e, Eigen::VectorXd::Zero(kMaxMeasurements + 1), C7,
                      Eigen::MatrixXd::Identity(kMaxMeasurements + 1, kMaxMeasurements + 1)),
               Error);
}

}  // namespace
}  // namespace stride::balance
