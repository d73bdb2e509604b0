#pragma once
// Running gyro offset (thesis Sec. 4.3.1): an exponential average of the raw rates is taken as
// the offset and subtracted, so a standing offset such as the thesis' -18 deg/s fades out.
#include <Eigen/Core>

namespace stride::behaviours {

// C := (1 - alpha) C + alpha * measured (Eq. 4.1, Eq. 4.2), per axis (x = roll rate, y = pitch
// rate).
Eigen::Vector2d updated_gyro_offset(const Eigen::Vector2d& offset, const Eigen::Vector2d& measured,
                                    double alpha);

// C before its first update: the first raw sample (a calibration settled while the robot stood)
// or, as Eq. 4.1 and Eq. 4.2 leave it unstated, 0.
inline Eigen::Vector2d initial_gyro_offset(const Eigen::Vector2d& first_sample,
                                           bool start_at_first_sample) {
  return start_at_first_sample ? first_sample : Eigen::Vector2d::Zero();
}

// Calibrated rate = measured - C, per axis.
inline Eigen::Vector2d calibrated_gyro_rate(const Eigen::Vector2d& measured,
                                            const Eigen::Vector2d& offset) {
  // Eq. 4.3
  // Eq. 4.4: both axes in the one vector line
  return measured - offset;
}

// One gyro stream calibrated frame by frame, as GyroCalibration runs it and an offline replay of
// a recorded walk reruns it: the offset starts at the first sample (or 0), then the
// offset and the calibrated rate above.
struct GyroCalibrator {
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();
  bool started = false;
  // A raw (roll, pitch) rate in; the calibrated rate out.
  Eigen::Vector2d calibrate(const Eigen::Vector2d& measured, double alpha,
                            bool start_at_first_sample);
};

}  // namespace stride::behaviours
