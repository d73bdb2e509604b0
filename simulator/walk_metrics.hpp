#pragma once
// What a walking experiment reports, observed every control frame of one robot: steps, distance
// and speed both as the thesis measured them on the robot (forward kinematics between the feet in
// each double support, from the measured joint angles) and from the simulator's ground truth,
// average step length, torso pitch/roll extremes, and whether it fell.
#include <string>

#include "simulator/simulated_robot.hpp"

namespace stride::sim {

struct WalkMetricsResult {
  int steps = 0;                        // double supports entered after a single support
  double fk_distance = 0;               // m, sum of FK step lengths (thesis' method)
  double true_distance = 0;             // m, ground-truth advance of the feet's midpoint
  double torso_distance = 0;            // m, ground-truth torso advance
  double duration = 0;                  // s, observed time
  double fk_speed = 0, true_speed = 0;  // m/s
  double mean_step_length = 0;          // m, ground truth
  double pitch_min = 0, pitch_max = 0, roll_min = 0, roll_max = 0;  // rad, torso
  bool fell = false;
  double fell_at = -1;  // s
};

class WalkMetrics {
 public:
  explicit WalkMetrics(double load_threshold = 5.0) : threshold_(load_threshold) {}
  void observe(const SimulatedRobot& robot);  // once per control frame
  WalkMetricsResult result() const;

 private:
  double threshold_;
  int lfoot_ = -2, rfoot_ = -2;  // link indices, looked up on the first frame (-1: no such link)
  bool started_ = false;
  double t0_ = 0, t_ = 0;
  double x0_mid_ = 0, x0_torso_ = 0, x_mid_ = 0, x_torso_ = 0;
  bool in_single_support_ = false;
  WalkMetricsResult r_;
};

std::string walk_metrics_text(const WalkMetricsResult& r);

}  // namespace stride::sim
