#pragma once
// Seeded calibration errors (a scene's <calibration>, see CalibrationSpread): each chosen servo's
// zero error drawn from N(0, sd) with the scene seed.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "simulator/scene/device_description.hpp"
#include "simulator/scene/noise_source.hpp"

namespace stride::sim {

// A joint driven by another joint's motor (URDF mimic): its name -> (leader, multiplier).
using MimicJoints = std::map<std::string, std::pair<std::string, double>>;

// Adds a drawn error to each chosen servo's offset, in the device file's servo order; a mimic joint
// whose leader is drawn for shares the leader's error (times its multiplier), listed or not, since
// one motor and one encoder set both. Returns the errors added, by joint, in that order. Throws
// Error("file:line: ...") for a joint with no servo, changing nothing.
std::vector<std::pair<std::string, double>> draw_calibration_errors(DeviceDescription& devices,
                                                                    const CalibrationSpread& spread,
                                                                    const MimicJoints& mimic,
                                                                    NoiseSource& noise);

// The leg servos: joints whose name holds Hip, Knee or Ankle.
bool is_leg_joint(const std::string& joint);

}  // namespace stride::sim
