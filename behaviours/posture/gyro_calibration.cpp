#include "behaviours/posture/gyro_calibration.hpp"

namespace stride::behaviours {

Eigen::Vector2d updated_gyro_offset(const Eigen::Vector2d& offset, const Eigen::Vector2d& measured,
                                    double alpha) {
  return (1 - alpha) * offset + alpha * measured;  // Eqs. 4.1-4.2
}

}  // namespace stride::behaviours
