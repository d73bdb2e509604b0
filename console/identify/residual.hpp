#pragma once
// The fit's residual: simulated minus logged sensor readings, each divided by the spread its
// sensor reads with, so that every row is in units of sensor noise. The motor currents are left
// out: they answer to the encoder offsets too, which a held robot's log does not resolve, and
// pulled the gains away from their true values (docs/identify.md).
#include <vector>

#include "console/identify/identify_log.hpp"

namespace stride::identify {

struct SensorSpread {
  double position = 1e-3;  // rad: encoder noise and a 12-bit quantum (1.5e-3 rad)
  double angle = 2e-3;     // rad: the IMU filter's angle noise (device file)
};

// Rows per frame: each joint's position, then (standing only) torso roll and pitch.
std::vector<double> residual(const IdentifyLog& log, const std::vector<LoggedFrame>& simulated,
                             const std::vector<int>& joints, const SensorSpread& spread = {});

// RMS of simulated minus logged position of LoLA joint `joint` (rad).
double rms_position_error(const IdentifyLog& log, const std::vector<LoggedFrame>& simulated,
                          int joint);

}  // namespace stride::identify
