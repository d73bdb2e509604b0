#include "behaviours/walking/pattern/pattern_plausibility.hpp"

#include <cmath>
#include <sstream>

#include "robot/nao/nao_dimensions.hpp"

namespace stride::walking {
namespace {

// What a NAO can walk, with margin: the thesis' strides take 0.4-1.16 s, its fastest walk was
// 0.24 m/s, and a step much longer than half the 16 cm sole or a foot lifted higher than a shin
// is beyond the legs of a 58 cm robot.
constexpr double kMinStride = 0.2, kMaxStride = 5.0;  // s
constexpr double kMaxStep = 0.12;                     // m per step
constexpr double kMaxFootLift = 0.08;                 // m
constexpr double kMaxSpeed = 0.6;                     // m/s
constexpr double kEarthGravity = 9.81;                // m/s^2

std::string g(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

}  // namespace

std::vector<std::string> plausibility_notes(const PatternParameters& p) {
  std::vector<std::string> notes;
  if (p.T_stride < kMinStride || p.T_stride > kMaxStride)
    notes.push_back("T_stride = " + g(p.T_stride) + " s: no NAO strides that " +
                    (p.T_stride < kMinStride ? "fast" : "slowly") + " (plausible " + g(kMinStride) +
                    " to " + g(kMaxStride) + " s; the thesis' walks use 0.4 to 1.16 s)");
  const double step = p.rhythmic.V_max * p.T_d() + p.rhythmic.V_min * p.T_s();  // Eq. 3.15
  if (step > kMaxStep)
    notes.push_back("step length " + g(step) + " m (from V_min, V_max, T_stride): longer than a " +
                    "NAO steps (plausible up to " + g(kMaxStep) + " m, the sole is " +
                    g(nao::kSoleLength) + " m long)");
  const double speed = 0.5 * (p.rhythmic.V_min + p.rhythmic.V_max);
  if (speed > kMaxSpeed)
    notes.push_back("rhythmic speed about " + g(speed) + " m/s: faster than a NAO walks " +
                    "(plausible up to " + g(kMaxSpeed) + " m/s; the thesis' NAO reached 0.24)");
  if (p.H_foot > kMaxFootLift)
    notes.push_back("H_foot = " + g(p.H_foot) + " m: higher than a NAO lifts its foot " +
                    "(plausible up to " + g(kMaxFootLift) + " m)");
  if (std::abs(p.gravity - kEarthGravity) > 0.05 * kEarthGravity)
    notes.push_back("gravity = " + g(p.gravity) + " m/s^2: not the Earth's 9.81");
  return notes;
}

}  // namespace stride::walking
