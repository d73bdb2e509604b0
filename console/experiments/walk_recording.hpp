#pragma once
// One experiment walk recorded frame by frame: the scene's controller runs as usual (timed
// changes included) and a WalkFrame observer keeps a row per control frame of what the thesis'
// Ch. 4 figures show. For a study over many walks use a sweep file (console/sweep); this is for
// one walk whose whole trace is wanted (the Kalman filter rerun offline, tests).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "console/plot/gnuplot_plot.hpp"
#include "console/session/walk_frame.hpp"
#include "simulator/walk_metrics.hpp"

namespace stride::experiments {

struct WalkSetup {
  std::string scene;
  std::uint64_t seed = 1;
  std::map<std::string, std::string> providers;                 // representation -> module
  std::vector<std::pair<std::string, std::string>> parameters;  // module, "field=value ..."
  double settle_seconds = 1.0;  // recorded after the pattern ends (the stop's inclination summit)
};

struct WalkRecording {
  std::vector<console::WalkFrame> frames;  // one per control frame
  sim::WalkMetricsResult metrics;          // whole run, the simulator's own accounting
  double walk_duration = 0;                // s, the pattern's duration
  double period = 0;                       // s, control period
  std::string walk_module;                 // PatternWalk or ConventionalWalk
};

// The frames as a table whose columns are WalkFrame's field names.
plot::Table trace_table(const WalkRecording& r);

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
