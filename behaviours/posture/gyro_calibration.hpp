#pragma once
// Running gyro offset (thesis Sec. 4.3.1): an exponential average of the raw rates is taken as
// the offset and subtracted, so a standing offset such as the thesis' -18 deg/s fades out.
#include <Eigen/Core>

namespace stride::behaviours {

// Eqs. 4.1-4.2: C := (1 - alpha) C + alpha * measured, per axis (x = roll rate, y = pitch rate).
Eigen::Vector2d updated_gyro_offset(const Eigen::Vector2d& offset, const Eigen::Vector2d& measured,
                                    double alpha);

// Eqs. 4.3-4.4: calibrated rate = measured - C.
inline Eigen::Vector2d calibrated_gyro_rate(const Eigen::Vector2d& measured,
                                            const Eigen::Vector2d& offset) {
  return measured - offset;
}

}  // namespace stride::behaviours
