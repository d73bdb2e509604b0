#pragma once
// One experiment walk recorded frame by frame: the scene's controller runs as usual and, after
// each control frame, a row of what the thesis' Ch. 4 figures show is appended (reference and
// modified hip/ankle angles, torso inclination estimated and true, waist velocity planned and
// true, CoP from the FSRs in the world frame, shoulder pitch, knee currents, IMU inputs).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "console/plot/gnuplot_plot.hpp"
#include "simulator/walk_metrics.hpp"

namespace stride::experiments {

// Trace columns, in this order (row[col(Trace::x)]).
enum class Trace : int {
  t,          // s, simulation time
  pattern_t,  // s, time since the walking pattern started (negative while standing)
  hip_pitch_ref_l,
  hip_pitch_mod_l,
  hip_roll_ref_l,
  hip_roll_mod_l,
  hip_pitch_ref_r,
  hip_pitch_mod_r,
  hip_roll_ref_r,
  hip_roll_mod_r,
  ankle_pitch_ref_l,
  ankle_pitch_mod_l,
  ankle_roll_ref_l,
  ankle_roll_mod_l,
  ankle_pitch_ref_r,
  ankle_pitch_mod_r,
  ankle_roll_ref_r,
  ankle_roll_mod_r,
  est_pitch,
  est_roll,
  est_pitch_rate,
  est_roll_rate,  // TorsoState (NaN without estimator)
  true_pitch,
  true_roll,
  true_pitch_rate,
  true_roll_rate,  // simulator ground truth
  imu_pitch,
  imu_roll,
  gyro_pitch,
  gyro_roll,  // raw IMU angles and rates
  waist_v_ref,
  waist_v,  // m/s forward: pattern and true torso
  torso_x,
  torso_y,
  feet_x,  // m, world
  cop_x,
  cop_y,  // m, world CoP from the FSRs (NaN airborne)
  zmp_ref_x,
  zmp_ref_y,  // m, pattern ZMP (Eq. 3.16)
  shoulder_pitch_l,
  shoulder_pitch_r,  // rad, commanded
  knee_current_l,
  knee_current_r,  // A
  count
};
constexpr int col(Trace c) {
  return static_cast<int>(c);
}
const std::vector<std::string>& trace_columns();

struct WalkSetup {
  std::string scene;
  std::uint64_t seed = 1;
  std::map<std::string, std::string> providers;                 // representation -> module
  std::vector<std::pair<std::string, std::string>> parameters;  // module, "field=value ..."
  double settle_seconds = 1.0;  // recorded after the pattern ends (the stop's inclination summit)
};

struct WalkRecording {
  plot::Table trace;
  sim::WalkMetricsResult metrics;  // whole run, the simulator's own accounting
  double walk_duration = 0;        // s, the pattern's duration
  double period = 0;               // s, control period
  std::string walk_module;         // PatternWalk or ConventionalWalk
};

// Loads and runs the scene for start delay + walk + settle; throws stride::Error for a bad
// scene, provider or parameter (the message names it).
WalkRecording record_walk(const WalkSetup& setup);

// What Sec. 4.3.4.2 reports per walk, over the pattern's duration.
struct WalkSummary {
  int steps = 0;
  double distance = 0;     // m, ground-truth advance of the feet's midpoint
  double fk_distance = 0;  // m, the thesis' measure: FK between the feet in each double support
  double speed = 0;        // m/s, distance / walk duration
  double step_length = 0;  // m, distance / steps
  double pitch_min = 0, pitch_max = 0, roll_min = 0, roll_max = 0;  // rad, true torso, walking
  bool fell = false;
  sim::Tip tipped = sim::Tip::None;  // first pass of sim::kTipAngle, looked for until the end
  double tipped_at = -1;             // s
};
WalkSummary summarize(const WalkRecording& r);

}  // namespace stride::experiments
