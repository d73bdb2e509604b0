// The torso sway measures against a trace of known motion: pitch = m + A sin(w t) over whole
// periods gives mean m, standard deviation A / sqrt(2) and rate RMS A w / sqrt(2); standing rows,
// rows after the pattern and everything from the first tilt past kTipAngle are left out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "console/experiments/torso_sway.hpp"

namespace stride::experiments {
namespace {

constexpr double kPeriod = 0.01, kMean = -0.02, kAmp = 0.05, kRoll = 0.03;
constexpr double kOmega = 2 * std::numbers::pi * 2.0;  // 2 Hz, the stride frequency

WalkRecording recording(double walk_duration, double tip_at) {
  WalkRecording r;
  r.period = kPeriod;
  r.walk_duration = walk_duration;
  r.trace.columns = trace_columns();
  for (int i = -100; i < 700; ++i) {  // 1 s standing, then the walk, then 2 s more
    const double tp = i * kPeriod;
    std::vector<double> row(col(Trace::count), 0.0);
    row[col(Trace::pattern_t)] = tp;
    row[col(Trace::true_pitch)] = tp < 0 ? 0.3 : kMean + kAmp * std::sin(kOmega * tp);
    row[col(Trace::true_pitch_rate)] = tp < 0 ? 9 : kAmp * kOmega * std::cos(kOmega * tp);
    row[col(Trace::true_roll)] = kRoll * std::sin(0.5 * kOmega * tp);
    if (tp >= tip_at) row[col(Trace::true_roll)] = 1.2;  // fallen over sideways
    if (tp > walk_duration) row[col(Trace::true_pitch)] = 1.0;
    r.trace.add_row(std::move(row));
  }
  return r;
}

TEST(TorsoSway, MeanSpreadAndRateOfAKnownSway) {
  const TorsoSway s = torso_sway(recording(3.995, 100));  // 400 rows = 8 whole pitch periods
  EXPECT_NEAR(s.seconds, 4.0, 1e-9);
  EXPECT_NEAR(s.pitch_mean, kMean, 1e-9);
  EXPECT_NEAR(s.pitch_sd, kAmp / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(s.pitch_rate_rms, kAmp * kOmega / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(s.roll_sd, kRoll / std::sqrt(2.0), 1e-6);
}

TEST(TorsoSway, StopsAtTheFirstTiltPastTheThreshold) {
  const TorsoSway s = torso_sway(recording(3.995, 1.995));  // tips after 4 pitch periods
  EXPECT_NEAR(s.seconds, 2.0, 1e-9);
  EXPECT_NEAR(s.pitch_mean, kMean, 1e-9);
  EXPECT_NEAR(s.pitch_sd, kAmp / std::sqrt(2.0), 1e-6);
}

TEST(TorsoSway, NoWalkingRowsGiveZeros) {
  const TorsoSway s = torso_sway(recording(3.995, -5));
  EXPECT_EQ(s.seconds, 0);
  EXPECT_EQ(s.pitch_sd, 0);
}

}  // namespace
}  // namespace stride::experiments
