// Pattern feet -> leg joint angles (Sec. 3.6) and the knee angles of Fig. 3.17.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {
namespace {

TEST(LegPoints, StretchedLegHangsStraightBelowTheHip) {
  const LegPoints l = leg_points(model::Side::Left, model::LegAngles{}, {0, 0, 0});
  EXPECT_NEAR((l.hip - Eigen::Vector3d(0, 0.05, -0.085)).norm(), 0, 1e-12);
  EXPECT_NEAR((l.knee - Eigen::Vector3d(0, 0.05, -0.185)).norm(), 0, 1e-12);
  EXPECT_NEAR((l.ankle - Eigen::Vector3d(0, 0.05, -0.2879)).norm(), 0, 1e-12);
}

// Law of cosines: knee bend for a hip-ankle distance d (0 when stretched).
double knee_for_distance(double d) {
  const double l1 = nao::kThighLength, l2 = nao::kTibiaLength;
  return std::acos(std::clamp((l1 * l1 + l2 * l2 - d * d) / (2 * l1 * l2), -1.0, 1.0)) * -1.0 +
         std::acos(-1.0);
}

double support_knee(const PatternSample& s, const LegJoints& q) {
  return s.support == SupportPhase::kLeft ? q.left[3] : q.right[3];
}

TEST(LegJoints, IkReproducesTheFeetRelativeToTheWaist) {
  const StretchedKneePattern w(preset("medium"));
  for (double t = 0.0; t <= w.duration(); t += 0.37) {
    const PatternSample s = w.sample(t);
    const LegJoints q = leg_joints(s);
    ASSERT_TRUE(q.reachable) << "t = " << t;
    const Eigen::Vector3d up(0, 0, nao::kFootHeight);
    EXPECT_NEAR((leg_points(model::Side::Left, q.left, s.waist).ankle - s.left_foot - up).norm(),
                0.0, 1e-9)
        << "t = " << t;
    EXPECT_NEAR((leg_points(model::Side::Right, q.right, s.waist).ankle - s.right_foot - up).norm(),
                0.0, 1e-9)
        << "t = " << t;
  }
}

// Fig. 3.17: the support knee nearly stretches at mid single support.
TEST(LegJoints, SupportKneeAtMidSupportMatchesTheHipAnkleDistance) {
  for (const char* name : {"slow", "medium", "fast", "fig3.14"}) {
    const StretchedKneePattern w(preset(name));
    const PatternParameters& p = w.parameters();
    for (int j = p.development_steps() + 1; j < p.steps - p.decay_steps(); ++j) {
      const PatternSample s = w.sample(j * p.T_step());
      const LegJoints q = leg_joints(s);
      const model::Side side =
          s.support == SupportPhase::kLeft ? model::Side::Left : model::Side::Right;
      const LegPoints leg = leg_points(side, side == model::Side::Left ? q.left : q.right, s.waist);
      EXPECT_NEAR(support_knee(s, q), knee_for_distance((leg.ankle - leg.hip).norm()), 1e-9)
          << name << " j = " << j;
    }
  }
}

// Smallest support-knee angle over a walk, and the smallest knee angle of any leg.
std::pair<double, double> smallest_knees(const std::vector<PatternSample>& walk) {
  double support = 10, any = 10;
  for (const PatternSample& s : walk) {
    const LegJoints q = leg_joints(s);
    if (s.support != SupportPhase::kDouble) support = std::min(support, support_knee(s, q));
    any = std::min({any, q.left[3], q.right[3]});
  }
  return {support, any};
}

// Fig. 3.17 and the low-speed walks of Table 4.4 stretch the support knee; the conventional
// pattern at 0.318 m (Table 4.5) keeps both knees bent all the time.
TEST(LegJoints, StretchedKneePatternStretchesConventionalStaysBent) {
  for (const char* name : {"fig3.14", "table4.4-5", "table4.4-10"}) {
    PatternParameters p = preset(name);
    p.steps = 24;
    EXPECT_LT(smallest_knees(sample_walk(StretchedKneePattern(p), 0.01)).first, 0.25) << name;
    p.H_foot = 0.02;
    EXPECT_GT(smallest_knees(sample_walk(ConventionalPattern(p), 0.01)).second, 0.65) << name;
  }
}

// Peak knee speed by finite differences: over the rhythmic steps and over the whole walk.
struct KneeSpeeds {
  double rhythmic = 0, whole = 0;
};
KneeSpeeds peak_knee_speeds(const char* name) {
  const StretchedKneePattern w(preset(name));
  const PatternParameters& p = w.parameters();
  const double from = (p.development_steps() + 1) * p.T_step();
  const double to = (p.steps - p.decay_steps() - 1) * p.T_step();
  constexpr double dt = 0.002;
  KneeSpeeds peak;
  double previous = leg_joints(w.sample(0)).left[3];
  for (double t = dt; t <= w.duration(); t += dt) {
    const double knee = leg_joints(w.sample(t)).left[3];
    const double speed = std::abs(knee - previous) / dt;
    peak.whole = std::max(peak.whole, speed);
    if (t > from && t < to) peak.rhythmic = std::max(peak.rhythmic, speed);
    previous = knee;
  }
  return peak;
}

// Sec. 4.3.4.2 lowers the waist as the speed rises. The straighter support legs of the slower
// settings need more knee travel to lift the swing foot H_foot within T_ssp: slow and medium ask
// for more than the NAO knee motor's no-load speed (399 deg/s, nao-facts.md), fast for less. The
// half-length first and last swings lift the foot as high in half the time.
TEST(LegJoints, KneeSpeedOfTheTable4_3SettingsFallsWithTheWaistHeight) {
  const double motor_no_load = 399.0 * std::numbers::pi / 180.0;
  const KneeSpeeds slow = peak_knee_speeds("slow"), medium = peak_knee_speeds("medium"),
                   fast = peak_knee_speeds("fast");
  EXPECT_GT(slow.rhythmic, medium.rhythmic);
  EXPECT_GT(medium.rhythmic, fast.rhythmic);
  EXPECT_GT(medium.rhythmic, motor_no_load) << medium.rhythmic;
  EXPECT_LT(fast.rhythmic, motor_no_load) << fast.rhythmic;
  for (const KneeSpeeds& k : {slow, medium, fast}) EXPECT_GT(k.whole, 1.8 * k.rhythmic);
}

}  // namespace
}  // namespace stride::walking
