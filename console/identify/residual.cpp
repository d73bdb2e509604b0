#include "console/identify/residual.hpp"

#include <cmath>

#include "robot/core/error.hpp"

namespace stride::identify {

std::vector<double> residual(const IdentifyLog& log, const std::vector<LoggedFrame>& simulated,
                             const std::vector<int>& joints, const SensorSpread& spread) {
  if (simulated.size() != log.frames.size())
    throw Error(log.file + ": the replay ended after " + std::to_string(simulated.size()) + " of " +
                std::to_string(log.frames.size()) + " frames");
  const SensorSpread& sp = spread;
  std::vector<double> r;
  r.reserve(log.frames.size() * (2 * joints.size() + 2));
  for (std::size_t f = 0; f < log.frames.size(); ++f) {
    const LoggedFrame &a = simulated[f], &b = log.frames[f];
    for (int j : joints) {
      r.push_back((a.position[j] - b.position[j]) / sp.position);
    }
    if (!log.held)
      for (int i = 0; i < 2; ++i) r.push_back((a.angles[i] - b.angles[i]) / spread.angle);
  }
  return r;
}

double rms_position_error(const IdentifyLog& log, const std::vector<LoggedFrame>& simulated,
                          int joint) {
  double sum = 0;
  const std::size_t n = std::min(simulated.size(), log.frames.size());
  for (std::size_t f = 0; f < n; ++f) {
    const double e = simulated[f].position[joint] - log.frames[f].position[joint];
    sum += e * e;
  }
  return n ? std::sqrt(sum / static_cast<double>(n)) : 0.0;
}

}  // namespace stride::identify
