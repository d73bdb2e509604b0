#include "behaviours/posture/gyro_calibration.hpp"

namespace stride::behaviours {

Eigen::Vector2d updated_gyro_offset(const Eigen::Vector2d& offset, const Eigen::Vector2d& measured,
                                    double alpha) {
  // Eq. 4.1
  // Eq. 4.2: both axes in the one vector line
  return (1 - alpha) * offset + alpha * measured;
}

Eigen::Vector2d GyroCalibrator::calibrate(const Eigen::Vector2d& measured, double alpha,
                                          bool start_at_first_sample) {
  if (!started) offset = initial_gyro_offset(measured, start_at_first_sample);
  started = true;
  offset = updated_gyro_offset(offset, measured, alpha);
  return calibrated_gyro_rate(measured, offset);
}

}  // namespace stride::behaviours
