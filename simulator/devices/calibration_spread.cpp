#include "simulator/devices/calibration_spread.hpp"

#include <algorithm>

#include "robot/core/error.hpp"

namespace stride::sim {

bool is_leg_joint(const std::string& joint) {
  for (const char* part : {"Hip", "Knee", "Ankle"})
    if (joint.find(part) != std::string::npos) return true;
  return false;
}

std::vector<std::pair<std::string, double>> draw_calibration_errors(DeviceDescription& devices,
                                                                    const CalibrationSpread& spread,
                                                                    const MimicJoints& mimic,
                                                                    NoiseSource& noise) {
  const auto chosen = [&](const std::string& joint) {
    return spread.joints.empty() ? is_leg_joint(joint)
                                 : std::find(spread.joints.begin(), spread.joints.end(), joint) !=
                                       spread.joints.end();
  };
  for (const std::string& j : spread.joints) {
    const bool found = std::any_of(devices.servos.begin(), devices.servos.end(),
                                   [&](const ServoSpec& s) { return s.joint == j; });
    if (!found)
      throw error_at(spread.file, spread.line,
                     "<calibration joints>: no servo for '" + j + "' in " + devices.file);
  }
  // Draw for the leaders first, in servo order, so a mimic joint finds its leader's error.
  std::map<std::string, double> drawn;
  for (const ServoSpec& s : devices.servos) {
    const auto m = mimic.find(s.joint);
    const bool follows = m != mimic.end() && chosen(m->second.first);
    if (chosen(s.joint) && !follows) drawn[s.joint] = noise.gaussian(spread.sd);
  }
  std::vector<std::pair<std::string, double>> added;
  for (ServoSpec& s : devices.servos) {
    double error = 0;
    if (const auto d = drawn.find(s.joint); d != drawn.end()) {
      error = d->second;
    } else if (const auto m = mimic.find(s.joint); m != mimic.end()) {
      const auto leader = drawn.find(m->second.first);
      if (leader == drawn.end()) continue;
      error = m->second.second * leader->second;
    } else {
      continue;
    }
    s.offset += error;
    added.emplace_back(s.joint, error);
  }
  return added;
}

}  // namespace stride::sim
