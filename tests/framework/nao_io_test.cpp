// Sensor conversion: per-foot and overall centres of pressure from the 8 FSRs.
#include <gtest/gtest.h>

#include "robot/nao/nao_dimensions.hpp"
#include "robot/runtime/nao_io_modules.hpp"

namespace stride {
namespace {

TEST(FootCop, IsTheForceWeightedMeanOfTheSensorPositions) {
  const double equal[4] = {3, 3, 3, 3};
  const Eigen::Vector2d centroid = (nao::kFsrPositions[0] + nao::kFsrPositions[1] +
                                    nao::kFsrPositions[2] + nao::kFsrPositions[3]) /
                                   4;
  EXPECT_TRUE(foot_cop(equal, nao::kFsrPositions.data()).isApprox(centroid, 1e-15));
  const double one[4] = {0, 0, 7, 0};
  EXPECT_EQ(foot_cop(one, nao::kFsrPositions.data()), nao::kFsrPositions[2]);
  const double none[4] = {0, 0, 0, 0};
  EXPECT_EQ(foot_cop(none, nao::kFsrPositions.data()), Eigen::Vector2d::Zero());
}

TEST(FsrSensorData, TotalsContactAndTorsoCopWithStraightLegs) {
  hal::SensorFrame s;  // all joints at 0: legs straight below the hips
  s.fsr = {10, 10, 10, 10, 0, 0, 0, 0.5};
  const auto f = fsr_sensor_data(s, 2.0);
  EXPECT_EQ(f.total_left, 40.0);
  EXPECT_EQ(f.total_right, 0.5);
  EXPECT_TRUE(f.contact_left);
  EXPECT_FALSE(f.contact_right);
  EXPECT_EQ(f.cop_right, nao::kFsrPositions[7]);
  ASSERT_TRUE(f.cop_torso_valid);
  // Soles at (0, +-HipOffsetY, -(HipOffsetZ + thigh + tibia + foot height)) in the torso frame.
  const double sole_z =
      -(nao::kHipOffsetZ + nao::kThighLength + nao::kTibiaLength + nao::kFootHeight);
  const Eigen::Vector3d left(f.cop_left.x(), f.cop_left.y() + nao::kHipOffsetY, sole_z);
  const Eigen::Vector3d right(f.cop_right.x(), f.cop_right.y() - nao::kHipOffsetY, sole_z);
  EXPECT_TRUE(f.cop_torso.isApprox((40 * left + 0.5 * right) / 40.5, 1e-12))
      << f.cop_torso.transpose();
  hal::SensorFrame empty;
  EXPECT_FALSE(fsr_sensor_data(empty, 2.0).cop_torso_valid);
}

}  // namespace
}  // namespace stride
