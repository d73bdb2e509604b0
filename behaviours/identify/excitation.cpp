#include "behaviours/identify/excitation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "behaviours/stand/stand.hpp"
#include "robot/nao/joint_limits.hpp"

namespace stride::behaviours {
namespace {

constexpr double kPi = std::numbers::pi;

// 0 -> 1 -> 0 over the excitation with raised-cosine ends: no jump in target or speed.
double envelope(const ExcitationParameters& p, double t) {
  if (t <= 0 || t >= p.duration) return 0;
  const double r = std::min(p.ramp, 0.5 * p.duration);
  const double edge = std::min(t, p.duration - t);
  return edge >= r ? 1.0 : 0.5 - 0.5 * std::cos(kPi * edge / r);
}

// Phase (cycles) of an exponential sweep from f0 to f1 over `duration`, at time t.
double chirp_cycles(double f0, double f1, double duration, double t) {
  if (std::abs(f1 - f0) < 1e-9) return f0 * t;
  const double k = std::log(f1 / f0) / duration;
  return f0 * (std::exp(k * t) - 1) / k;
}

// The hip roll joints swing outward only (from the posture to 2a away from the other leg), so
// that the feet never meet.
double outward(int joint) {
  if (joint == hal::index(hal::JointId::LHipRoll)) return 1;
  if (joint == hal::index(hal::JointId::RHipRoll)) return -1;
  return 0;
}

// Joint k's frequencies are scaled apart so that no two joints move in step.
double joint_scale(std::size_t k) {
  return 1.0 + 0.11 * static_cast<double>(k);
}

void leg_chirp(const ExcitationParameters& p, double t, double env, JointTargets& q) {
  for (std::size_t k = 0; k < kExcitedLegJoints.size(); ++k) {
    const double s = joint_scale(k);
    const double f0 = std::min(p.f_low, p.f_high) * s, f1 = std::max(p.f_low, p.f_high) * s;
    const double k_rate = std::log(f1 / f0) / p.duration;
    const double f_now = f0 * std::exp(k_rate * t);
    // Peak speed 2 pi f A stays within the bound at every frequency.
    const double a = std::min(p.amplitude, p.max_speed / (2 * kPi * f_now));
    const int j = kExcitedLegJoints[k];
    const double wave = std::sin(2 * kPi * chirp_cycles(f0, f1, p.duration, t));
    q[j] += env * a * (outward(j) != 0 ? outward(j) * (1 + wave) : wave);
  }
}

void leg_steps(const ExcitationParameters& p, double t, double env, JointTargets& q) {
  for (std::size_t k = 0; k < kExcitedLegJoints.size(); ++k) {
    const double cycles = p.f_low * joint_scale(k) * t;
    const double sign = std::fmod(cycles, 1.0) < 0.5 ? 1.0 : -1.0;
    const int j = kExcitedLegJoints[k];
    // limit_rate bounds the edges' speed
    q[j] += env * p.amplitude * (outward(j) != 0 ? outward(j) * (1 + sign) : sign);
  }
}

void squat(const ExcitationParameters& p, double t, double env, JointTargets& q) {
  using hal::JointId;
  // Hip and ankle pitch by -a, knee by 2a: the torso stays upright above the feet.
  const double f = std::min(p.f_low, p.max_speed / (2 * kPi * p.amplitude));
  const double a = env * p.amplitude * (0.5 - 0.5 * std::cos(2 * kPi * f * t));
  for (auto [hip, knee, ankle] :
       {std::array{JointId::LHipPitch, JointId::LKneePitch, JointId::LAnklePitch},
        std::array{JointId::RHipPitch, JointId::RKneePitch, JointId::RAnklePitch}}) {
    q[hal::index(hip)] -= a;
    q[hal::index(knee)] += 2 * a;
    q[hal::index(ankle)] -= a;
  }
}

void weight_shift(const ExcitationParameters& p, double t, double env, JointTargets& q) {
  using hal::JointId;
  // Hip roll and ankle roll opposite: the pelvis moves sideways over feet that stay flat.
  const double f = std::min(p.f_low, p.max_speed / (2 * kPi * p.amplitude));
  const double a = env * p.amplitude * std::sin(2 * kPi * f * t);
  for (auto [hip, ankle] : {std::array{JointId::LHipRoll, JointId::LAnkleRoll},
                            std::array{JointId::RHipRoll, JointId::RAnkleRoll}}) {
    q[hal::index(hip)] += a;
    q[hal::index(ankle)] -= a;
  }
}

}  // namespace

JointTargets excitation_base() {
  return stand_posture(StandParameters{});
}

JointTargets excitation_targets(const ExcitationParameters& p, double t) {
  JointTargets q = excitation_base();
  const double env = envelope(p, t);
  if (env > 0) {
    switch (p.motion) {
      case ExcitationMotion::chirp:
        leg_chirp(p, t, env, q);
        break;
      case ExcitationMotion::steps:
        leg_steps(p, t, env, q);
        break;
      case ExcitationMotion::squat:
        squat(p, t, env, q);
        break;
      case ExcitationMotion::weight_shift:
        weight_shift(p, t, env, q);
        break;
    }
  }
  for (int i : kExcitedLegJoints) {  // the only joints a motion moves
    const auto& r = nao::kJointLimits[i];
    q[i] = std::clamp(q[i], r.lower + kExcitationLimitMargin, r.upper - kExcitationLimitMargin);
  }
  return q;
}

void limit_rate(JointTargets& current, const JointTargets& target, double max_speed, double dt) {
  const double step = max_speed * dt;
  for (int i = 0; i < hal::kNumJoints; ++i)
    current[i] += std::clamp(target[i] - current[i], -step, step);
}

}  // namespace stride::behaviours
