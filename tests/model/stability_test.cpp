#include <gtest/gtest.h>

#include <array>

#include "robot/model/dynamics/stability_points.hpp"
#include "robot/model/kinematics/dh.hpp"
#include "robot/model/kinematics/support_polygon.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::model {
namespace {

// (Eigen vectors initialised from {} stay uninitialised, so every field is spelled out.)
SegmentMotion segment(double mass, const Eigen::Vector3d& com,
                      const Eigen::Vector3d& acc = Eigen::Vector3d::Zero(),
                      const Eigen::Vector3d& dl = Eigen::Vector3d::Zero()) {
  return {mass, com, acc, dl};
}

TEST(SupportPolygon, OneFootIsTheSoleRectangle) {
  const FootContact left{Side::Left, trans(0.1, 0.2, 0)};
  const ConvexPolygon p = support_polygon(std::span(&left, 1));
  EXPECT_EQ(p.size, 4);
  EXPECT_NEAR(p.area(), nao::kSoleLength * nao::kSoleWidth, 1e-15);
  // Centre of the sole: half the width away from the nearest (long) edge.
  const Eigen::Vector2d centre(0.1 + nao::kSoleCentreX, 0.2 + nao::kSoleCentreYLeft);
  EXPECT_NEAR(stability_margin(centre, p), nao::kSoleWidth / 2, 1e-15);
  EXPECT_NEAR(stability_margin(centre + Eigen::Vector2d(0, 0.1), p), -(0.1 - nao::kSoleWidth / 2),
              1e-15);
  // Beyond a corner the distance is to the corner.
  const Eigen::Vector2d corner = centre + Eigen::Vector2d(nao::kSoleLength, nao::kSoleWidth) / 2;
  EXPECT_NEAR(stability_margin(corner + Eigen::Vector2d(0.03, 0.04), p), -0.05, 1e-15);
}

TEST(SupportPolygon, RightFootMirrorsTheLeft) {
  const auto l = sole_corners(Side::Left), r = sole_corners(Side::Right);
  for (int i = 0; i < 4; ++i) {
    bool mirrored = false;
    for (int j = 0; j < 4; ++j)
      mirrored |= (l[i] - Eigen::Vector2d(r[j].x(), -r[j].y())).norm() < 1e-15;
    EXPECT_TRUE(mirrored);
  }
}

TEST(SupportPolygon, TwoParallelFeetSpanTheOuterEdges) {
  const std::array feet = {FootContact{Side::Left, trans(0, 0.05, 0)},
                           FootContact{Side::Right, trans(0, -0.05, 0)}};
  const ConvexPolygon p = support_polygon(feet);
  EXPECT_EQ(p.size, 4);
  const double outer = 0.05 + nao::kSoleCentreYLeft + nao::kSoleWidth / 2;
  EXPECT_NEAR(p.area(), nao::kSoleLength * 2 * outer, 1e-14);
  EXPECT_GT(p.area(), 0);  // counter-clockwise
  // The gap between the feet is inside the double-support polygon.
  EXPECT_GT(stability_margin(Eigen::Vector2d(nao::kSoleCentreX, 0), p), 0.0);
}

TEST(SupportPolygon, StaggeredFeetGiveAHexagon) {
  const std::array feet = {FootContact{Side::Left, trans(0.05, 0.05, 0)},
                           FootContact{Side::Right, trans(-0.05, -0.05, 0)}};
  EXPECT_EQ(support_polygon(feet).size, 6);
}

TEST(StabilityPoints, StaticBodyZmpIsTheCoMProjection) {
  const std::array segments = {segment(1.0, Eigen::Vector3d(0.02, 0.01, 0.3)),
                               segment(3.0, Eigen::Vector3d(-0.02, 0.03, 0.1))};
  const Eigen::Vector2d z = zmp_multibody(segments);
  EXPECT_NEAR(z.x(), (0.02 - 0.06) / 4, 1e-15);
  EXPECT_NEAR(z.y(), (0.01 + 0.09) / 4, 1e-15);
}

TEST(StabilityPoints, PointMassZmpIsTheCartTableLaw) {  // Eq. 2.5 with constant height
  const Eigen::Vector3d com(0.01, -0.02, 0.26), acc(0.5, -0.3, 0);
  const Eigen::Vector2d z = zmp_point_mass(com, acc, 5.0);
  EXPECT_NEAR(z.x(), 0.01 - 0.26 / kGravity * 0.5, 1e-15);
  EXPECT_NEAR(z.y(), -0.02 + 0.26 / kGravity * 0.3, 1e-15);
  // The multi-body form with one segment agrees, angular momentum rate included.
  const Eigen::Vector3d dl(0.01, -0.02, 0);
  const std::array one = {SegmentMotion{5.0, com, acc, dl}};
  EXPECT_LT((zmp_multibody(one) - zmp_point_mass(com, acc, 5.0, dl)).norm(), 1e-15);
}

TEST(StabilityPoints, CopIsTheForceWeightedMean) {
  const std::array<double, 3> f = {1, 3, 0};
  const std::array<Eigen::Vector3d, 3> p = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.2, 0),
                                            Eigen::Vector3d(5, 5, 5)};
  EXPECT_LT((*centre_of_pressure(f, p) - Eigen::Vector3d(0.075, 0.15, 0)).norm(), 1e-15);
  const std::array<double, 3> none = {0, 0, 0};
  EXPECT_FALSE(centre_of_pressure(none, p).has_value());
}

TEST(StabilityPoints, NaoFsrCopOfEvenLoadIsTheSensorCentroid) {
  const std::array<double, 8> f = {1, 1, 1, 1, 0, 0, 0, 0};
  const auto cop = nao_fsr_centre_of_pressure(f, trans(0, 0.05, 0), trans(0, -0.05, 0));
  ASSERT_TRUE(cop.has_value());
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int i = 0; i < 4; ++i) mean += nao::kFsrPositions[i] / 4;
  EXPECT_LT((cop->head<2>() - (mean + Eigen::Vector2d(0, 0.05))).norm(), 1e-15);
}

TEST(StabilityPoints, FriCmpAndZmpCoincideForAStaticRobot) {  // Sec. 2.1.3 (Popovic et al.)
  const SegmentMotion foot = segment(0.3, Eigen::Vector3d(0.02, 0.05, 0.02));
  const std::array body = {segment(4.0, Eigen::Vector3d(0.01, 0.0, 0.3))};
  const Eigen::Vector2d fri = foot_rotation_indicator(foot, body);
  const std::array all = {foot, body[0]};
  EXPECT_LT((fri - zmp_multibody(all)).norm(), 1e-15);
  const Eigen::Vector3d com = (0.3 * foot.com + 4.0 * body[0].com) / 4.3;
  EXPECT_LT((cmp_from_com_motion(com, Eigen::Vector3d::Zero()) - zmp_multibody(all)).norm(), 1e-15);
}

TEST(StabilityPoints, CmpLeavesTheZmpWhenAngularMomentumChanges) {
  // Eq. 2.11/2.12: with a rate of angular momentum the CMP (reaction through the CoM) and ZMP split
  // by dL_y / (M g) for a CoM at rest.
  const Eigen::Vector3d com(0, 0, 0.3);
  const Eigen::Vector3d dl(0, 0.2, 0);
  const Eigen::Vector2d zmp = zmp_point_mass(com, Eigen::Vector3d::Zero(), 5.0, dl);
  const Eigen::Vector2d cmp = cmp_from_com_motion(com, Eigen::Vector3d::Zero());
  EXPECT_NEAR(cmp.x() - zmp.x(), 0.2 / (5.0 * kGravity), 1e-15);
  // A forward-leaning reaction force moves the CMP back along the force line.
  EXPECT_NEAR(cmp_from_ground_reaction(com, Eigen::Vector3d(1, 0, 10)).x(), -0.03, 1e-15);
}

TEST(StabilityPoints, FriLeavesTheFootWhenTheBodyAccelerates) {
  const SegmentMotion foot = segment(0.3, Eigen::Vector3d(0.0, 0.05, 0.02));
  const std::array body = {
      segment(4.0, Eigen::Vector3d(0.0, 0.0, 0.3), Eigen::Vector3d(2.0, 0, 0))};
  // Both CoMs above x = 0: only the body's inertial force (4 kg * 2 m/s^2 at 0.3 m) tips it.
  const double fx = -(0.3 * 4.0 * 2.0) / (0.3 * kGravity + 4.0 * kGravity);
  EXPECT_NEAR(foot_rotation_indicator(foot, body).x(), fx, 1e-15);
}

}  // namespace
}  // namespace stride::model
