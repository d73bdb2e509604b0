#include "behaviours/walking/steps/online_walk.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "behaviours/walking/pattern/point_mass_zmp.hpp"
#include "behaviours/walking/steps/walk_joints.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/model/kinematics/nao_leg_ik.hpp"

namespace stride::walking {

namespace {

constexpr int kKeptSteps = 4;  // steps sampled at most one back and one ahead of the current

// Candidate i (1..kFallbacks) after `to` from `from` failed: half, a quarter and an eighth of the
// change, none of it, then `from` slowed to 3/4, 1/2, 1/4 and rest.
constexpr int kFallbacks = 8;
StepVelocity fallback(const StepVelocity& from, const StepVelocity& to, int i) {
  constexpr double kShare[] = {1.0, 0.5, 0.25, 0.125, 0.0};
  const double f = i < 5 ? kShare[i] : 0.0, slow = i < 5 ? 1.0 : 1.0 - 0.25 * (i - 4);
  return {slow * from.forward + f * (to.forward - from.forward),
          slow * from.sideways + f * (to.sideways - from.sideways),
          slow * from.turn + f * (to.turn - from.turn)};
}

double side_of(Foot f) {
  return f == Foot::kLeft ? 1.0 : -1.0;
}

}  // namespace

OnlineWalk::OnlineWalk(const PatternParameters& p, const StepLimits& limits, const Pose2& at,
                       const Pose2& reference, double early_share)
    : p_(p),
      limits_(limits),
      T_(p.T_step()),
      T_s_(p.T_s()),
      origin_(at),
      reference_origin_(reference),
      early_share_(early_share) {
  if (!(early_share >= 0.1 && early_share <= 1.0))
    throw Error("early_share must be in [0.1, 1] (got " + short_number(early_share) + ")");
  if (auto e = validation_error(p)) throw Error(*e);
  if (const std::string e = limits_error(limits); !e.empty()) throw Error(e);
}

void OnlineWalk::advance(double t, bool walk, const StepVelocity& wanted,
                         const StepVelocity& correction) {
  if (next_step_ == 0 && !walk) return;  // standing, asked to stand
  while (!stopping() && decision_time(next_step_) <= t) plan(walk, wanted, correction);
}

void OnlineWalk::plan(bool walk, const StepVelocity& wanted, const StepVelocity& correction) {
  const int k = next_step_;
  wanted_in_range_ = walk ? within_range(wanted, limits_) : StepVelocity{};
  const StepVelocity granted_before = k == 0 ? StepVelocity{} : reference_.back().to();
  const StepVelocity previous = k == 0 ? StepVelocity{} : step(k - 1).to();
  StepKind kind = k == 0 ? StepKind::kFirst : StepKind::kMiddle;
  if (!walk && k > 0 && can_stop_within_a_step(granted_before, limits_)) {
    kind = StepKind::kLast;
    granted_ = {};
    steps_total_ = k + 1;
  } else {
    granted_ = next_step_velocity(granted_before, wanted_in_range_, limits_);
  }
  StepVelocity planned = granted_;
  if (kind == StepKind::kMiddle && std::isfinite(correction.forward + correction.sideways)) {
    const StepVelocity moved = within_range(
        {granted_.forward + correction.forward, granted_.sideways + correction.sideways, 0.0},
        limits_);
    planned.forward = moved.forward;
    planned.sideways = moved.sideways;
  }
  if (std::isfinite(correction.turn)) planned.turn += correction.turn;
  const Pose2 start = k == 0 ? origin_ : step(k - 1).end();
  // A step whose leg IK leaves the joint limits or the legs' reach is planned again with less of
  // its change, then slower than the step before: what the walk grants is what it can do.
  const StepVelocity wanted_granted = granted_, wanted_planned = planned;
  for (int i = 0;; ++i) {
    steps_.emplace_back(p_, k, kind, previous, planned, start);
    ++next_step_;
    if (kind == StepKind::kLast || i == kFallbacks || within_reach(k)) break;
    steps_.pop_back();
    --next_step_;
    ++shortened_;
    granted_ = fallback(granted_before, wanted_granted, i + 1);
    planned = fallback(previous, wanted_planned, i + 1);
  }
  reference_.emplace_back(p_, k, kind, granted_before, granted_,
                          k == 0 ? reference_origin_ : reference_.back().end());
  while (static_cast<int>(steps_.size()) > kKeptSteps) {
    steps_.pop_front();
    reference_.pop_front();
    ++first_kept_;
  }
}

bool OnlineWalk::within_reach(int k) const {
  constexpr int kSamples = 50;
  // Checked with the waist 2 mm higher: a leg that reaches there reaches between the samples.
  constexpr double kReachMargin = 0.002;  // m
  const double from = decision_time(k), to = decision_time(k + 1);
  for (int i = 0; i <= kSamples; ++i) {
    WalkSample s = sample(from + (to - from) * i / kSamples);
    s.waist.z() += kReachMargin;
    const LegJoints q = leg_joints(s).legs;
    if (q.beyond_limits != 0 || !q.reachable) return false;
  }
  return true;
}

const WaistStep& OnlineWalk::step(int k) const {
  return steps_[std::clamp(k - first_kept_, 0, static_cast<int>(steps_.size()) - 1)];
}

Pose2 OnlineWalk::foothold(int j) const {
  if (j <= 0 || next_step_ == 0) return origin_;
  if (j >= next_step_) return step(next_step_ - 1).end();
  return step(j).start();
}

double OnlineWalk::swing_start(int j) const {
  return std::max(0.0, j * T_ - T_s_);
}

double OnlineWalk::swing_end(int j) const {
  const double end = j * T_ + T_s_;
  return stopping() ? std::min(steps_total_ * T_, end) : end;
}

FootPose OnlineWalk::foot_at(Foot f, int j) const {
  const Pose2 h = foothold(j);
  const Eigen::Vector2d p = point_in(h, 0.0, side_of(f) * p_.d_0);
  return {{p.x(), p.y(), 0.0}, h.yaw};
}

int OnlineWalk::landings_after(double t, std::span<Landing> out) const {
  int n = 0;
  const int last = stopping() ? steps_total_ : next_step_ - 1;  // the last swing planned
  for (int j = std::max(0, static_cast<int>(std::floor((t + T_s_) / T_)) - 1);
       j <= last && n < static_cast<int>(out.size()); ++j) {
    if (swing_end(j) <= t) continue;
    const Foot f = Footsteps::swing_foot(j);
    out[n++] = {f, foot_at(f, j + 1)};
  }
  return n;
}

FootPose OnlineWalk::foot(Foot f, double t) const {
  const auto at = [&](int j) { return foot_at(f, j); };
  int j = static_cast<int>(std::floor((t + T_s_) / T_));
  if (stopping()) j = std::min(j, steps_total_);
  if (j >= 0 && Footsteps::swing_foot(j) != f) --j;
  if (j < 0) return at(0);
  if (t >= swing_end(j)) return at(j + 1);
  const FootPose from = at(j - 1), to = at(j + 1);
  const double progress = (t - swing_start(j)) / (swing_end(j) - swing_start(j));
  // The cycloid's share of the way along the walk (it does not depend on the distance).
  const double share = cycloid_share(progress);
  FootPose out;
  // The share of Eq. 3.11 along the walk; the sideways move and the turn (no thesis equation: its
  // walk is straight) by the same law within the first early_share_ of the swing, so that the hip
  // roll and the one HipYawPitch servo, which lag, have arrived when the foot lands.
  const double early = cycloid_share(progress / early_share_);
  const double heading = foothold(j - 1).yaw;
  const Eigen::Vector2d d = (to.position - from.position).head<2>();
  const Eigen::Vector2d local = rotated(-heading, d.x(), d.y());
  out.position = from.position;
  out.position.head<2>() += rotated(heading, share * local.x(), early * local.y());
  out.position.z() = cycloid(1.0, p_.H_foot, progress).y();
  out.yaw = wrap_angle(from.yaw + early * wrap_angle(to.yaw - from.yaw));
  return out;
}

SupportPhase OnlineWalk::support(double t) const {
  if (!(t > 0.0) || ended(t)) return SupportPhase::kDouble;
  const int k = static_cast<int>(std::floor(t / T_ + 0.5));  // nearest boundary
  if (t < swing_start(k) || t >= swing_end(k)) return SupportPhase::kDouble;
  return Footsteps::swing_foot(k) == Foot::kLeft ? SupportPhase::kRight : SupportPhase::kLeft;
}

WalkSample OnlineWalk::sample(double t) const {
  WalkSample s;
  s.t = t;
  s.left = foot(Foot::kLeft, std::max(t, 0.0));
  s.right = foot(Foot::kRight, std::max(t, 0.0));
  s.support = support(t);
  s.torso_yaw = model::torso_yaw_between(s.left.yaw, s.right.yaw);
  if (next_step_ == 0 || !(t > 0.0) || ended(t)) {
    const bool before = next_step_ == 0 || !(t > 0.0);
    s.frame = before ? origin_ : step(steps_total_ - 1).end();
    s.reference = before ? reference_origin_ : reference_.back().end();
    s.waist = {s.frame.x, s.frame.y, p_.z_max};
    s.zmp = s.waist.head<2>();
    return s;
  }
  const int k = std::min(static_cast<int>(t / T_), next_step_ - 1);
  const WaistStep& w = step(k);
  const double u = t - k * T_;
  const LocalMotion m = w.local(u);
  s.step = k;
  s.frame = w.frame_at(u);
  const int r = std::max(0, k - first_kept_);  // a step being checked has no reference yet
  s.reference = r < static_cast<int>(reference_.size()) ? reference_[r].frame_at(u) : s.frame;
  s.velocity = {m.forward.v, m.sideways.v, m.heading.v};
  const double yaw = s.frame.yaw, rate = m.heading.v;
  const Eigen::Vector2d xy = point_in(s.frame, 0.0, m.sway.p);
  // The walk frame's velocity and acceleration turned into the world, the sway's offset with it.
  const Eigen::Vector2d v = rotated(yaw, m.forward.v - rate * m.sway.p, m.sideways.v + m.sway.v);
  const Eigen::Vector2d a = rotated(
      yaw, m.forward.a - rate * m.sideways.v - m.heading.a * m.sway.p - 2.0 * rate * m.sway.v,
      m.sideways.a + rate * m.forward.v + m.sway.a - rate * rate * m.sway.p);
  s.waist = {xy.x(), xy.y(), m.height.p};
  s.waist_velocity = {v.x(), v.y(), m.height.v};
  s.waist_acceleration = {a.x(), a.y(), m.height.a};
  s.zmp = point_mass_zmp(s.waist, s.waist_acceleration, p_.gravity);
  return s;
}

}  // namespace stride::walking
