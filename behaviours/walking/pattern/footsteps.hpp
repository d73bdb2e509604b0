#pragma once
// Footholds and cycloid swing-foot trajectories (Eq. 3.11, Eq. 3.12, Eq. 3.15). Every step boundary
// t = j T_step is the middle of a single support; there the support foot stands at the waist's
// forward position X_j (Eq. 3.12), and in the rhythmic phase the swing foot passes it too.
// Swing j is centred at j T_step (left foot for even j, right for odd j) and carries the foot from
// X_{j-1} to X_{j+1}; swing 0 (from the stand) and swing `steps` (closing the feet) are half as
// long in time and distance. Positions are sole-frame origins: on the ground under the ankle.
#include <Eigen/Core>

#include "behaviours/walking/pattern/forward_motion.hpp"
#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::walking {

enum class Foot { kLeft, kRight };
enum class SupportPhase { kDouble, kLeft, kRight };

// The cycloid of Eq. 3.11 with delta = H_foot / (2 alpha): (forward, up) after `progress` in [0, 1]
// of a swing that covers `distance`. alpha = distance / (2 pi) (Eq. 3.15 in the rhythmic phase).
Eigen::Vector2d cycloid(double distance, double H_foot, double progress);
// The share of the cycloid's way covered at progress 0..1 (its x over the distance).
double cycloid_share(double progress);

// alpha = (V_max T_d + V_min T_s) / pi (Eq. 3.15), one rhythmic step length over pi.
double synchronisation_alpha(const SpeedLevel& level, double T_s, double T_d);

class Footsteps {
 public:
  Footsteps(const PatternParameters& p, const ForwardMotion& forward);
  Eigen::Vector3d foot(Foot f, double t) const;
  SupportPhase support(double t) const;
  int swings() const { return steps_ + 1; }
  // Forward position of foothold j (= X_j), j in [-1, steps + 1], clamped at the ends.
  double foothold(int j) const;
  // Swing j (0..steps): which foot, and when it leaves and lands.
  static Foot swing_foot(int j) { return j % 2 == 0 ? Foot::kLeft : Foot::kRight; }
  double swing_start(int j) const;
  double swing_end(int j) const;

 private:
  double T_step_, T_s_, d_0_, H_foot_;
  int steps_;
  Eigen::VectorXd footholds_;  // X_0..X_steps
};

}  // namespace stride::walking
