#include "behaviours/posture/gyro_calibration.hpp"

namespace stride::behaviours {

Eigen::Vector2d updated_gyro_offset(const Eigen::Vector2d& offset, const Eigen::Vector2d& measured,
                                    double alpha) {
  // Eq. 4.1
  // Eq. 4.2: both axes in the one vector line
  return (1 - alpha) * offset + alpha * measured;
}

}  // namespace stride::behaviours
