#pragma once
// Running gyro offset (thesis Sec. 4.3.1): an exponential average of the raw rates is taken as
// the offset and subtracted, so a standing offset such as the thesis' -18 deg/s fades out.
#include <Eigen/Core>

namespace stride::behaviours {

// Eqs. 4.1-4.2: C := (1 - alpha) C + alpha * measured, per axis (x = roll rate, y = pitch rate).
Eigen::Vector2d updated_gyro_offset(const Eigen::Vector2d& offset, const Eigen::Vector2d& measured,
                                    double alpha);

// C before its first update: the first raw sample (a calibration settled while the robot stood)
// or, as Eqs. 4.1-4.2 leave it unstated, 0.
inline Eigen::Vector2d initial_gyro_offset(const Eigen::Vector2d& first_sample,
                                           bool start_at_first_sample) {
  return start_at_first_sample ? first_sample : Eigen::Vector2d::Zero();
}

// Eqs. 4.3-4.4: calibrated rate = measured - C.
inline Eigen::Vector2d calibrated_gyro_rate(const Eigen::Vector2d& measured,
                                            const Eigen::Vector2d& offset) {
  return measured - offset;
}

}  // namespace stride::behaviours
