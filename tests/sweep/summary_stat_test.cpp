// Per-run summaries against signals of known shape: pitch = m + A sin(w t) over whole periods
// gives mean m, standard deviation A / sqrt(2), RMS of its rate A w / sqrt(2); a constant knee
// current I over 20 s integrates to I * 20 s, so U * integral is Eq. 4.16's energy; the window
// keeps the walking frames (pattern time from 0 up to the walk's end) and a stop condition ends
// it at the first tilt.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "console/sweep/summary_stat.hpp"

namespace stride::sweep {
namespace {

using S = SummarySpec::Stat;
constexpr double kPeriod = 0.01, kMean = -0.02, kAmp = 0.05;
constexpr double kOmega = 2 * std::numbers::pi * 2.0;  // 2 Hz, the stride frequency

// Frames from 1 s before the pattern to 2 s after a 3.995 s walk; returns the stat's result.
double over_walk(S stat, bool inclusive, double tip_at = 100, double walk = 3.995) {
  WindowedStat w({true, 0}, {true, walk}, inclusive, SummaryStat(stat, 0.2));
  for (int i = -100; i < 700; ++i) {
    const double tp = i * kPeriod, t = 2.0 + tp;
    const double pitch = tp < 0 ? 0.3 : tp > walk ? 1.0 : kMean + kAmp * std::sin(kOmega * tp);
    if (!w.admits(t, tp)) continue;
    if (tp >= tip_at) {  // the `until` condition held on this frame
      w.stop();
      continue;
    }
    w.add(t, stat == S::Rms ? kAmp * kOmega * std::cos(kOmega * tp) : pitch);
  }
  return w.result(kPeriod);
}

TEST(SummaryStat, MeanSpreadAndRateOfAKnownSway) {
  EXPECT_EQ(over_walk(S::Count, true), 400);  // 8 whole pitch periods
  EXPECT_NEAR(over_walk(S::Mean, true), kMean, 1e-9);
  EXPECT_NEAR(over_walk(S::Sd, true), kAmp / std::sqrt(2.0), 1e-6);
  EXPECT_NEAR(over_walk(S::Rms, true), kAmp * kOmega / std::sqrt(2.0), 1e-6);
  // The sine's crests fall halfway between two frames: the sampled extremes are A cos(w T / 2).
  const double crest = kAmp * std::cos(kOmega * kPeriod / 2);
  EXPECT_NEAR(over_walk(S::Min, true), kMean - crest, 1e-12);
  EXPECT_NEAR(over_walk(S::Max, true), kMean + crest, 1e-12);
  EXPECT_NEAR(over_walk(S::Final, true) - over_walk(S::First, true), over_walk(S::Change, true),
              1e-15);
}

TEST(SummaryStat, ToLeavesOutTheFrameOnTheEndThroughKeepsIt) {
  EXPECT_EQ(over_walk(S::Count, true, 100, 4.0), 401);
  EXPECT_EQ(over_walk(S::Count, false, 100, 4.0), 400);
}

TEST(SummaryStat, StopsAtTheFirstTiltAndAnEmptyWindowIsNaN) {
  EXPECT_EQ(over_walk(S::Count, true, 1.995), 200);  // tips after 4 pitch periods
  EXPECT_NEAR(over_walk(S::Sd, true, 1.995), kAmp / std::sqrt(2.0), 1e-6);
  EXPECT_TRUE(std::isnan(over_walk(S::Mean, true, -5)));
  EXPECT_EQ(over_walk(S::Count, true, -5), 0);
}

TEST(SummaryStat, IntegralOfAConstantCurrentIsEq416BeforeTheVoltage) {
  SummaryStat s(S::Integral, 0);
  for (int k = 0; k < 2000; ++k) s.add(k * kPeriod, 0.5);  // 20 s of 10 ms samples
  EXPECT_NEAR(21.6 * s.result(kPeriod), 21.6 * 0.5 * 20.0, 1e-9);
  SummaryStat ramp(S::Sum, 0);
  for (int j = 1; j <= 100; ++j) ramp.add(j, 0.01 * j);
  EXPECT_NEAR(ramp.result(kPeriod), 0.01 * 100 * 101 / 2, 1e-12);
}

TEST(SummaryStat, FirstPastIsTheFirstTimeTheMagnitudePassesTheThreshold) {
  SummaryStat s(S::FirstPast, 0.4);
  for (int k = 0; k < 100; ++k) s.add(k * 0.1, -0.05 * k);  // |v| > 0.4 from k = 9
  EXPECT_NEAR(s.result(0.01), 0.9, 1e-12);
  SummaryStat never(S::FirstPast, 0.4);
  never.add(0, 0.1);
  EXPECT_EQ(never.result(0.01), -1);
}

}  // namespace
}  // namespace stride::sweep
