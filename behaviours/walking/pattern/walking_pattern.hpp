#pragma once
// The thesis' walking pattern (Ch. 3) and the conventional constant-height pattern it is
// compared with (Sec. 4.3.4.3), sampled at any time t of the walk.
#include <vector>

#include <Eigen/Core>

#include "behaviours/walking/pattern/footsteps.hpp"
#include "behaviours/walking/pattern/forward_motion.hpp"
#include "behaviours/walking/pattern/lateral_motion.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::walking {

// World frame: x forward, y left, z up, origin on the ground midway between the starting feet.
struct PatternSample {
  double t = 0.0;
  Eigen::Vector3d waist = Eigen::Vector3d::Zero();  // torso origin
  Eigen::Vector3d waist_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d waist_acceleration = Eigen::Vector3d::Zero();
  Eigen::Vector3d left_foot = Eigen::Vector3d::Zero();  // sole-frame origins
  Eigen::Vector3d right_foot = Eigen::Vector3d::Zero();
  SupportPhase support = SupportPhase::kDouble;
  Eigen::Vector2d zmp = Eigen::Vector2d::Zero();  // the ZMP of Eq. 3.16
};

// What both patterns share: forward and lateral waist motion, footsteps, ZMP.
class HorizontalPattern {
 public:
  double duration() const { return forward_.duration(); }
  const PatternParameters& parameters() const { return p_; }
  const Footsteps& footsteps() const { return feet_; }

 protected:
  explicit HorizontalPattern(const PatternParameters& p);  // validates, throws stride::Error
  PatternSample sample_with_height(double t, const Motion1d& z) const;

  PatternParameters p_;
  ForwardMotion forward_;
  LateralMotion lateral_;
  Footsteps feet_;
};

// Stretched-knee pattern: 3-D waist motion (Sec. 3.3), cycloid feet (Sec. 3.4, Sec. 3.5).
class StretchedKneePattern : public HorizontalPattern {
 public:
  explicit StretchedKneePattern(const PatternParameters& p) : HorizontalPattern(p) {}
  PatternSample sample(double t) const;
};

// Conventional pattern: the same footsteps and horizontal waist motion, the waist held at the
// constant height z_conventional as in 3D-LIPM walking, so the knees stay bent.
class ConventionalPattern : public HorizontalPattern {
 public:
  explicit ConventionalPattern(const PatternParameters& p) : HorizontalPattern(p) {}
  PatternSample sample(double t) const;
};

// The whole walk at period dt, from t = 0 to the end inclusive.
template <class Pattern>
std::vector<PatternSample> sample_walk(const Pattern& pattern, double dt) {
  std::vector<PatternSample> out;
  const int n = static_cast<int>(pattern.duration() / dt + 1e-9);
  out.reserve(n + 1);
  for (int i = 0; i <= n; ++i) out.push_back(pattern.sample(i * dt));
  return out;
}

}  // namespace stride::walking
