#pragma once
// The absurd-but-finite bounds every robot, scene and command is held to before the physics
// engine sees a number (docs/scenes.md "Limits"). Beyond them an engine asserts, overflows or loses all
// precision; within them a run may still diverge, which the divergence check reports.
#include <sstream>
#include <string>

namespace stride::limits {

inline constexpr double kMaxPosition = 1e4;     // m: |coordinate| of anything placed or moved
inline constexpr double kMaxLength = 1e3;       // m: a shape's size, a joint's or a shape's offset
inline constexpr double kMinLength = 1e-6;      // m: the smallest shape size
inline constexpr double kMaxMass = 1e5;         // kg per link
inline constexpr double kMinInertia = 1e-12;    // kg m^2: smallest principal moment (no denormals)
inline constexpr double kMaxInertia = 1e5;      // kg m^2: largest principal moment
inline constexpr double kMaxFrameMass = 1e-6;   // kg: the most a link without inertia may weigh
inline constexpr double kMaxForce = 1e7;        // N (and N m for joint efforts)
inline constexpr double kMaxSpeed = 1e4;        // rad/s or m/s: joint velocity limits
inline constexpr double kMaxJointRange = 1e3;   // rad or m: |lower|, |upper| of a joint
inline constexpr double kMaxMimicFactor = 1e3;  // |multiplier|, |offset| of a mimic joint
inline constexpr double kMaxGravity = 1e3;      // m/s^2
inline constexpr double kMaxDuration = 1e6;     // s: pushes and runs (about 11.6 days)
inline constexpr int kMaxLinks = 1000;          // links per robot

// "" when `seconds` is a duration a run or push may have, else e.g.
// "1e+300 s outside [0, 1e+06]".
inline std::string duration_problem(double seconds) {
  if (seconds >= 0 && seconds <= kMaxDuration) return "";
  std::ostringstream s;
  s << seconds << " s outside [0, " << kMaxDuration << "]";
  return s.str();
}

}  // namespace stride::limits
