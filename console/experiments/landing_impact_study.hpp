#pragma once
// Thesis Ch. 6 realised in simulation (its future work): a foot set down on the floor by the
// position-controlled leg (the LandingPosition module), and by the impedance law of Eq. 6.17 in
// torque mode (LandingImpedance); the contact force the floor feels on the way.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace stride::experiments {

struct LandingOptions {
  std::string scene;  // a fixed-base robot, left sole above the floor, 1 ms control period
  bool impedance = false;
  double speed = 0.2;                            // m/s, the sole's planned descent
  double depth = 0.005;                          // m, how far below the floor the plan ends
  double duration = 0.8;                         // s
  Eigen::Vector3d stiffness{2000, 2000, 300};    // K, N/m (x, y, z in the torso frame)
  Eigen::Vector3d damping{20, 20, 15};           // B, N s/m
  double rot_stiffness = 20, rot_damping = 0.3;  // N m/rad, N m s/rad
};

struct LandingResult {
  double touchdown = -1;   // s, first contact of the left sole
  double impulse = 0;      // N s the floor gave in the 10 ms from touchdown
  double peak_force = 0;   // N, largest 10 ms mean of the vertical force in the 0.2 s after it
  double peak_at = 0;      // s after touchdown (end of that 10 ms window)
  int lift_offs = 0;       // times the sole left the floor again after touchdown (rebounds)
  double final_force = 0;  // N, mean over the last 0.1 s
  double max_torque = 0;   // N m, largest commanded leg torque (impedance)
  std::vector<std::pair<double, double>> trace;  // time (s), vertical floor force (N) per frame
};

// Throws stride::Error if the scene does not fit the study.
LandingResult run_landing(const LandingOptions& options);

}  // namespace stride::experiments
