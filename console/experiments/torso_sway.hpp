#pragma once
// How the torso moved while walking, the measures behind Sec. 4.3.4.2's remarks on the PD gains
// (a larger K_p leans the upper body back, too large a K_p makes it oscillate, K_d at -0.06 or
// below makes it shake): lean = mean pitch, sway = pitch spread, shake = pitch-rate RMS.
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

struct TorsoSway {
  double seconds = 0;         // s of walking the figures cover (up to a fall or tip)
  double pitch_mean = 0;      // rad, > 0 forward
  double pitch_sd = 0;        // rad
  double pitch_rate_rms = 0;  // rad/s
  double roll_sd = 0;         // rad
};

// Over the rows with 0 <= pattern_t <= walk_duration, stopping before the first row whose true
// pitch or roll passes sim::kTipAngle (a fall's own motion is not the walk's sway).
TorsoSway torso_sway(const WalkRecording& r);

}  // namespace stride::experiments
