#include "console/sweep/summary_stat.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stride::sweep {

void SummaryStat::add(double t, double v) {
  if (n_ == 0) {
    first_ = min_ = max_ = v;
  } else {
    min_ = std::min(min_, v);
    max_ = std::max(max_, v);
  }
  last_ = v;
  sum_ += v;
  sum_sq_ += v * v;
  if (past_at_ < 0 && std::abs(v) > threshold_) past_at_ = t;
  ++n_;
}

double SummaryStat::result(double period) const {
  using S = SummarySpec::Stat;
  if (stat_ == S::Count) return static_cast<double>(n_);
  if (stat_ == S::FirstPast) return past_at_;
  if (n_ == 0) return std::numeric_limits<double>::quiet_NaN();
  const double n = static_cast<double>(n_);
  switch (stat_) {
    case S::Min:
      return min_;
    case S::Max:
      return max_;
    case S::Mean:
      return sum_ / n;
    case S::Rms:
      return std::sqrt(sum_sq_ / n);
    case S::Sd: {
      const double mean = sum_ / n;
      return std::sqrt(std::max(0.0, sum_sq_ / n - mean * mean));
    }
    case S::First:
      return first_;
    case S::Final:
      return last_;
    case S::Change:
      return last_ - first_;
    case S::Sum:
      return sum_;
    case S::Integral:
      return sum_ * period;
    default:
      return std::numeric_limits<double>::quiet_NaN();
  }
}

bool WindowedStat::admits(double t, double pattern_t) const {
  if (stopped_ || from_.of(t, pattern_t) < from_.value) return false;
  const double to = to_.of(t, pattern_t);
  // `to` leaves out a frame within 1e-9 s of its end: the pattern's last sample is not the walk.
  return inclusive_ ? to <= to_.value : to < to_.value - 1e-9;
}

}  // namespace stride::sweep
