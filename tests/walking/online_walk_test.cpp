// The online step planner (behaviours/walking/steps): requests become steps within the limits, the
// pattern stays continuous across steps whatever the requests do, a rhythmic step covers exactly
// the requested speed, turning keeps the torso midway between the feet, and a stop ends standing.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "behaviours/walking/pattern/forward_motion.hpp"
#include "behaviours/walking/steps/online_walk.hpp"
#include "behaviours/walking/steps/walk_joints.hpp"

namespace stride::walking {
namespace {

constexpr double kDt = 0.001;

struct Phase {
  double until;  // walk time (s)
  bool walk;
  StepVelocity v;
};

// Samples the walk every millisecond through the phases, then until it has ended.
std::vector<WalkSample> run(OnlineWalk& w, const std::vector<Phase>& phases, double end) {
  std::vector<WalkSample> out;
  std::size_t i = 0;
  for (double t = 0.0; t <= end; t += kDt) {
    while (i + 1 < phases.size() && t >= phases[i].until) ++i;
    w.advance(t, phases[i].walk, phases[i].v);
    out.push_back(w.sample(t));
  }
  return out;
}

const std::vector<Phase> kScenario = {{3.0, true, {0.2, 0, 0}},
                                      {6.0, true, {0, 0.05, 0}},
                                      {9.0, true, {0, 0, 0.5}},
                                      {11.0, true, {0.2, 0, 0.0}},
                                      {99.0, false, {}}};

TEST(OnlineWalk, RhythmicStepCoversTheRequestedMeanSpeed) {
  const PatternParameters p = preset("medium");
  for (double v : {0.05, 0.12, 0.2, -0.06}) {
    const SpeedLevel level = level_for_mean_speed(p, v);
    EXPECT_NEAR(rhythmic_step(level, p.T_s(), p.T_d(), p.T_step()).p, v * p.T_step(), 1e-12) << v;
    EXPECT_NEAR((level.V_max - level.V_min) / v, (0.19 - 0.18) / 0.18505, 1e-12) << v;
  }
}

TEST(OnlineWalk, GrantsTheRequestWithinRangeAndItsChangePerStep) {
  const StepLimits l;
  const StepVelocity asked{1.0, -1.0, 2.0};
  const StepVelocity in_range = within_range(asked, l);
  EXPECT_EQ(in_range.forward, l.max_forward);
  EXPECT_EQ(in_range.sideways, -l.max_sideways);
  EXPECT_EQ(in_range.turn, l.max_turn);
  const StepVelocity first = next_step_velocity({}, asked, l);
  EXPECT_DOUBLE_EQ(first.forward, l.forward_per_step);
  EXPECT_DOUBLE_EQ(first.sideways, -l.sideways_per_step);
  EXPECT_DOUBLE_EQ(first.turn, l.turn_per_step);
  EXPECT_EQ(within_range({NAN, INFINITY, -INFINITY}, l), StepVelocity{});
  EXPECT_EQ(limits_error(l), "");
  StepLimits bad = l;
  bad.turn_per_step = 0;
  EXPECT_EQ(limits_error(bad), "turn_per_step must be > 0 (a walk could never stop)");
  bad.max_forward = NAN;
  EXPECT_EQ(limits_error(bad), "max_forward must be a finite value >= 0 (got nan)");
}

TEST(OnlineWalk, StaysContinuousThroughEveryChangeAndEndsStanding) {
  const PatternParameters p = preset("medium");
  OnlineWalk w(p, StepLimits{}, {}, {});
  const std::vector<WalkSample> s = run(w, kScenario, 16.0);
  ASSERT_TRUE(w.ended(16.0)) << "still walking after the stop request";
  double worst_waist = 0, worst_velocity = 0, worst_foot = 0, worst_yaw = 0;
  // Velocities within the walk: Eq. 3.8 leaves the first step's lateral velocity free (the
  // thesis' a1 = A_l (3 - pi^2 / 2) / T_step = -7.7 mm/s), so the walk starts and ends (the first
  // step mirrored) with that jump, as the thesis' pattern does.
  for (std::size_t i = 1; i < s.size(); ++i) {
    worst_waist = std::max(worst_waist, (s[i].waist - s[i - 1].waist).norm());
    if (s[i].step >= 0 && s[i - 1].step >= 0)
      worst_velocity =
          std::max(worst_velocity, (s[i].waist_velocity - s[i - 1].waist_velocity).norm());
    worst_foot = std::max({worst_foot, (s[i].left.position - s[i - 1].left.position).norm(),
                           (s[i].right.position - s[i - 1].right.position).norm()});
    worst_yaw = std::max(worst_yaw, std::abs(wrap_angle(s[i].torso_yaw - s[i - 1].torso_yaw)));
    ASSERT_TRUE(s[i].waist.allFinite() && s[i].zmp.allFinite()) << s[i].t;
  }
  // In 1 ms: the waist moves under 0.4 mm and its speed by under 2 mm/s (the acceleration stays
  // below 2 m/s^2: no step joins with a jump); a swinging foot moves under 2 mm.
  EXPECT_LT(worst_waist, 4e-4);
  EXPECT_LT(worst_velocity, 2e-3);
  EXPECT_LT(worst_foot, 2e-3);
  EXPECT_LT(worst_yaw, 3e-3);  // the feet turn within half their swing
  const WalkSample& last = s.back();
  EXPECT_EQ(last.support, SupportPhase::kDouble);
  EXPECT_DOUBLE_EQ(last.waist.z(), p.z_max);
  EXPECT_NEAR((last.left.position - last.right.position).norm(), 2 * p.d_0, 1e-12);
  EXPECT_NEAR(last.left.yaw, last.right.yaw, 1e-12);
  const Eigen::Vector2d between = 0.5 * (last.left.position + last.right.position).head<2>();
  EXPECT_NEAR((between - last.waist.head<2>()).norm(), 0.0, 1e-12);
}

TEST(OnlineWalk, FollowsTheRequestsIntegratedOverTime) {
  OnlineWalk w(preset("medium"), StepLimits{}, {}, {});
  const std::vector<WalkSample> s = run(w, kScenario, 16.0);
  // Forward 0.2 m/s for about 3 s after a ramp of 4 steps, then sideways and turning in place.
  const WalkSample& at3 = s[3000];
  EXPECT_GT(at3.frame.x, 0.45);
  EXPECT_LT(at3.frame.x, 0.6);
  const WalkSample& at6 = s[6000];
  // Sideways from the step planned after 3 s: 0.03 then 0.05 m/s (its change per step).
  const double T = 0.25;
  const auto ramp = [&](double from, double to) {  // distance of a quartic change over a step
    return development_quartic(from, to, 0.0, T).at(T).p;
  };
  EXPECT_NEAR(at6.frame.y - at3.frame.y, ramp(0, 0.03) + ramp(0.03, 0.05) + 2.25 * 0.05, 1e-6);
  const WalkSample& at9 = s[9000];
  EXPECT_NEAR(at9.frame.yaw - at6.frame.yaw, ramp(0, 0.25) + ramp(0.25, 0.5) + 2.25 * 0.5, 1e-9);
  EXPECT_NEAR(at9.velocity.turn, 0.5, 1e-9);  // granted in full by then
  // Rhythmic forward steps: the walk frame's mean speed over a step is the request.
  const WalkSample& a = s[2000];
  const WalkSample& b = s[2250];
  EXPECT_NEAR(std::hypot(b.frame.x - a.frame.x, b.frame.y - a.frame.y) / 0.25, 0.2, 1e-6);
}

TEST(OnlineWalk, TurningFeetStayWithinTheJointLimitsAndTheTorsoBetweenThem) {
  OnlineWalk w(preset("medium"), StepLimits{}, {}, {});
  const std::vector<WalkSample> s = run(w, kScenario, 16.0);
  int beyond = 0, unreachable = 0;
  double widest = 0;
  for (const WalkSample& x : s) {
    const WalkJoints j = leg_joints(x);
    const LegJoints& q = j.legs;
    beyond += q.beyond_limits != 0;
    unreachable += !q.reachable;
    EXPECT_LT(j.yaw_error, 1e-10) << x.t;  // both feet flat and turned as planned
    EXPECT_NEAR(wrap_angle(j.torso_yaw - x.torso_yaw), 0.0, 0.02) << x.t;
    EXPECT_EQ(q.left[0], q.right[0]);
    widest = std::max(widest, std::abs(wrap_angle(x.left.yaw - x.right.yaw)));
  }
  EXPECT_EQ(beyond, 0);
  EXPECT_EQ(unreachable, 0);
  EXPECT_NEAR(widest, 0.125, 1e-9);  // turning 0.5 rad/s opens the feet by one step's turn
}

TEST(OnlineWalk, LandingsAreTheFootholdsTheFeetReach) {
  OnlineWalk w(preset("medium"), StepLimits{}, {}, {});
  std::array<Landing, 4> next;
  for (double t = 0.0; t < 4.0; t += kDt) {
    w.advance(t, true, {0.1, 0.02, 0.3});
    const int n = w.landings_after(t, next);
    const WalkSample s = w.sample(t);
    if (s.support == SupportPhase::kDouble) continue;  // the next landing is planned at lift-off
    ASSERT_GE(n, 1) << t;
    const FootPose& f = next[0].foot == Foot::kLeft ? s.left : s.right;
    // The landing promised for the swinging foot is where it is headed: it gets there.
    const WalkSample later = w.sample(t + 0.25);  // landed, not yet lifted again
    const FootPose& there = next[0].foot == Foot::kLeft ? later.left : later.right;
    EXPECT_LT((there.position - next[0].pose.position).norm(), 1e-9) << t;
    EXPECT_NEAR(there.yaw, next[0].pose.yaw, 1e-9) << t;
    EXPECT_GT(f.position.z(), 0.0) << t;
  }
}

TEST(OnlineWalk, StandingAskedToStandNeverSteps) {
  OnlineWalk w(preset("medium"), StepLimits{}, {0.5, -0.2, 1.0}, {});
  for (double t = 0.0; t < 2.0; t += 0.01) w.advance(t, false, {0.2, 0, 0});
  EXPECT_EQ(w.planned_steps(), 0);
  const WalkSample s = w.sample(2.0);
  EXPECT_EQ(s.step, -1);
  EXPECT_DOUBLE_EQ(s.waist.x(), 0.5);
  EXPECT_DOUBLE_EQ(s.torso_yaw, 1.0);
}

// Limits raised beyond what the legs reach: steps whose leg IK would leave the joint limits are
// planned again with half their change, so every frame stays within them and less is granted.
TEST(OnlineWalk, StepsBeyondTheLegsReachAreShortened) {
  const StepLimits wide{1.0, 1.0, 1.0, 5.0, 1.0, 1.0, 5.0};
  OnlineWalk w(preset("medium"), wide, {}, {});
  const std::vector<Phase> phases = {{2.0, true, {1.0, 0, 0}},
                                     {4.0, true, {0, -1.0, 0}},
                                     {6.0, true, {0, 0, 5.0}},
                                     {99.0, false, {}}};
  int beyond = 0;
  double fastest = 0;
  for (const WalkSample& x : run(w, phases, 9.0)) {
    beyond += leg_joints(x).legs.beyond_limits != 0 || !leg_joints(x).legs.reachable;
    fastest = std::max(fastest, x.velocity.forward);
  }
  EXPECT_EQ(beyond, 0);
  EXPECT_GT(w.shortened(), 10);
  EXPECT_LT(fastest, 0.9);  // far less than asked
  EXPECT_GT(fastest, 0.2);  // but more than the default limits grant
  EXPECT_TRUE(w.ended(9.0));
}

}  // namespace
}  // namespace stride::walking
