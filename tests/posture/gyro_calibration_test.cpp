// Sec. 4.3.1: the running gyro offset (Eqs. 4.1-4.4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "behaviours/posture/gyro_calibration.hpp"

namespace stride::behaviours {
namespace {

TEST(GyroCalibration, OffsetApproachesAConstantBiasInClosedForm) {
  const double alpha = 0.001;  // thesis value
  // The thesis' standing offset of about -18 deg/s on one axis, a small one on the other.
  const Eigen::Vector2d bias(-18 * std::numbers::pi / 180, 0.05);
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();
  for (int n = 1; n <= 5000; ++n) {
    offset = updated_gyro_offset(offset, bias, alpha);
    const double remaining = std::pow(1 - alpha, n);
    if (n == 1 || n == 693 || n == 5000) {
      EXPECT_NEAR(offset.x(), bias.x() * (1 - remaining), 1e-12) << n;
      EXPECT_NEAR(offset.y(), bias.y() * (1 - remaining), 1e-12) << n;
      const Eigen::Vector2d calibrated = calibrated_gyro_rate(bias, offset);
      EXPECT_NEAR(calibrated.x(), bias.x() * remaining, 1e-12) << n;
    }
  }
  // ln 2 / alpha frames halve the bias; after 5000 frames (50 s at 10 ms) under 1 % remains.
  EXPECT_LT(std::abs(calibrated_gyro_rate(bias, offset).x()), 0.01 * std::abs(bias.x()));
}

TEST(GyroCalibration, AlphaZeroKeepsTheOffsetAndAlphaOneTakesTheSample) {
  const Eigen::Vector2d offset(0.1, -0.2), sample(0.3, 0.4);
  EXPECT_EQ(updated_gyro_offset(offset, sample, 0.0), offset);
  EXPECT_EQ(updated_gyro_offset(offset, sample, 1.0), sample);
  EXPECT_EQ(calibrated_gyro_rate(sample, sample), Eigen::Vector2d::Zero());
}

TEST(GyroCalibration, InitialOffsetIsTheFirstSampleOrZero) {
  const Eigen::Vector2d first(0.02, -0.314);
  EXPECT_EQ(initial_gyro_offset(first, true), first);
  EXPECT_EQ(initial_gyro_offset(first, false), Eigen::Vector2d::Zero());
  // Started at the sample, a constant bias is removed from the first calibrated rate on.
  const Eigen::Vector2d c = updated_gyro_offset(initial_gyro_offset(first, true), first, 0.001);
  EXPECT_NEAR(calibrated_gyro_rate(first, c).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace stride::behaviours
