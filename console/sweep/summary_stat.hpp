#pragma once
// One number from a signal over the frames of a window: min, max, mean, RMS, standard deviation,
// first, final, change (final - first), sum, integral (sum x control period), count, or the first
// time |value| passed a threshold. Sums run in frame order; the standard deviation is
// sqrt(max(0, mean(x^2) - mean^2)), as the Ch. 4 sway figures compute it.
#include "console/sweep/sweep_spec.hpp"

namespace stride::sweep {

class SummaryStat {
 public:
  SummaryStat(SummarySpec::Stat stat, double threshold) : stat_(stat), threshold_(threshold) {}

  void add(double t, double v);
  // NaN when no frame entered (FirstPast: -1 when the threshold was never passed).
  double result(double period) const;

 private:
  SummarySpec::Stat stat_;
  double threshold_;
  long n_ = 0;
  double first_ = 0, last_ = 0, min_ = 0, max_ = 0, sum_ = 0, sum_sq_ = 0;
  double past_at_ = -1;
};

// A bound of a summary's window, tested on each frame against the walking pattern's own clock
// (walk marks) or simulation time, so a frame on a bound falls on the side the pattern puts it.
struct WindowBound {
  bool walk = false;
  double value = 0;  // s: pattern time for walk marks, simulation time otherwise
  double of(double t, double pattern_t) const { return walk ? pattern_t : t; }
};

// A SummaryStat fed the frames of a window [from, to) or [from, to] until it is stopped (the
// summary's `until` condition held on a frame inside the window).
class WindowedStat {
 public:
  WindowedStat(WindowBound from, WindowBound to, bool inclusive, SummaryStat stat)
      : from_(from), to_(to), inclusive_(inclusive), stat_(stat) {}

  // Whether a frame at (t, pattern_t) counts: inside the window and not stopped.
  bool admits(double t, double pattern_t) const;
  void stop() { stopped_ = true; }
  void add(double t, double v) { stat_.add(t, v); }
  double result(double period) const { return stat_.result(period); }

 private:
  WindowBound from_, to_;
  bool inclusive_;
  bool stopped_ = false;
  SummaryStat stat_;
};

}  // namespace stride::sweep
