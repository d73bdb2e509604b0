#include "console/experiments/torso_sway.hpp"

#include <cmath>

namespace stride::experiments {

TorsoSway torso_sway(const WalkRecording& r) {
  TorsoSway s;
  int n = 0;
  double pitch = 0, pitch2 = 0, rate2 = 0, roll = 0, roll2 = 0;
  for (const auto& row : r.trace.rows) {
    const double tp = row[col(Trace::pattern_t)];
    if (tp < 0) continue;
    if (tp > r.walk_duration) break;
    const double p = row[col(Trace::true_pitch)], q = row[col(Trace::true_roll)];
    if (std::abs(p) > sim::kTipAngle || std::abs(q) > sim::kTipAngle) break;
    const double w = row[col(Trace::true_pitch_rate)];
    ++n;
    pitch += p, pitch2 += p * p, rate2 += w * w, roll += q, roll2 += q * q;
  }
  if (n == 0) return s;
  s.seconds = n * r.period;
  s.pitch_mean = pitch / n;
  s.pitch_sd = std::sqrt(std::max(0.0, pitch2 / n - s.pitch_mean * s.pitch_mean));
  s.pitch_rate_rms = std::sqrt(rate2 / n);
  const double roll_mean = roll / n;
  s.roll_sd = std::sqrt(std::max(0.0, roll2 / n - roll_mean * roll_mean));
  return s;
}

}  // namespace stride::experiments
