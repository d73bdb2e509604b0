#pragma once
// Excitation motions for identifying a NAO's servos (docs/identify.md): joint targets around a
// base posture, each bounded in joint range (a margin inside the limits) and in commanded speed,
// ending in the base posture. Free functions of time; the Excitation module only plays them.
#include <array>

#include "robot/framework/reflect.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride::behaviours {

// chirp / steps: every leg joint at once (robot held in the air), each at its own frequencies so
// that their effects can be told apart; squat / weight_shift: standing on both feet.
enum class ExcitationMotion { chirp, steps, squat, weight_shift };

}  // namespace stride::behaviours

namespace stride {
template <>
struct EnumNames<behaviours::ExcitationMotion> {
  static constexpr std::string_view type_name = "ExcitationMotion";
  static constexpr std::array<std::string_view, 4> names{"chirp", "steps", "squat", "weight_shift"};
};
}  // namespace stride

namespace stride::behaviours {

struct ExcitationParameters {
  STRIDE_FIELDS(ExcitationParameters);
  STRIDE_FIELD(ExcitationMotion, motion) = ExcitationMotion::chirp;
  // rad: largest departure of a joint from the base posture
  STRIDE_FIELD(double, amplitude, "rad", Range{0, 0.4}) = 0.15;
  // rad/s: no commanded joint moves faster
  STRIDE_FIELD(double, max_speed, "rad/s", Range{0.05, 4}) = 1.5;
  // Hz: chirp start; steps: the slowest joint's switching rate
  STRIDE_FIELD(double, f_low, "Hz", Range{0.05, 5}) = 0.3;
  STRIDE_FIELD(double, f_high, "Hz", Range{0.05, 5}) = 2.5;  // Hz: chirp end
  // s from the measured pose to the base posture, then excitation
  STRIDE_FIELD(double, start_delay, "s", Range{0.5, 60}) = 1.5;
  // s of excitation, envelope included
  STRIDE_FIELD(double, duration, "s", Range{1, 600}) = 8;
  // s of smooth envelope at each end of the excitation
  STRIDE_FIELD(double, ramp, "s", Range{0.1, 10}) = 1;
  STRIDE_FIELD(double, stiffness, "", Range{0, 1}) = 1;

  static constexpr std::string_view kTypeName = "ExcitationParameters";
};

using JointTargets = std::array<double, hal::kNumJoints>;

// Kept this far inside every joint limit (rad).
inline constexpr double kExcitationLimitMargin = 0.05;

// The posture every motion starts from and ends in: the stand posture.
JointTargets excitation_base();

// The motion's targets `t` seconds after the excitation starts (t < 0 or past the duration: the
// base), before the speed bound; each leg joint clamped within its limits less the margin,
// the others at the base.
JointTargets excitation_targets(const ExcitationParameters& p, double t);

// Moves `current` toward `target` by at most max_speed * dt per joint: the speed bound.
void limit_rate(JointTargets& current, const JointTargets& target, double max_speed, double dt);

// The leg joints a motion moves (LoLA indices; HipYawPitch, one motor for both legs, stays still).
inline constexpr std::array<int, 10> kExcitedLegJoints = {8, 9, 10, 11, 12, 13, 14, 15, 16, 17};

}  // namespace stride::behaviours
