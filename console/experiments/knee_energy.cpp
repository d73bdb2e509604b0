#include "console/experiments/knee_energy.hpp"

#include <cmath>
#include <numeric>

namespace stride::experiments {

double electrical_work(std::span<const double> current, double voltage, double dt) {
  return voltage * std::accumulate(current.begin(), current.end(), 0.0) * dt;  // Eq. 4.16
}

double mean_work(std::span<const double> works) {
  if (works.empty()) return 0;
  return std::accumulate(works.begin(), works.end(), 0.0) / works.size();  // Eq. 4.17
}

double population_std(std::span<const double> values) {
  if (values.empty()) return 0;
  const double m = mean_work(values);
  double sum = 0;
  for (double v : values) sum += (v - m) * (v - m);
  return std::sqrt(sum / values.size());
}

double saving_percent(double ours, double baseline) {
  return 100.0 * (baseline - ours) / baseline;
}

}  // namespace stride::experiments
