#pragma once
// The log's commands replayed on the simulated robot with candidate servo parameters: the same
// plant `stride run` simulates (ODE, the URDF and device file), started at the log's first
// measured pose, held in the air (fixed base) or standing as the log says, sensors noise-free
// and unquantised so that the cost is smooth in the parameters.
#include <string>
#include <vector>

#include "console/identify/identify_log.hpp"
#include "simulator/scene/device_description.hpp"

namespace stride::identify {

struct RobotFiles {
  std::string urdf;
  std::string devices;
};

// The robot's files: `robot` is a URDF (its devices beside it as <name>.devices.xml) or empty
// for the shipped NAO. Throws stride::Error naming a file that is missing.
RobotFiles robot_files(const std::string& robot);

// The simulated sensors at each logged frame, the log's commands sent after each.
std::vector<LoggedFrame> replay(const IdentifyLog& log, const RobotFiles& robot,
                                const std::vector<sim::ServoOverride>& servos);

}  // namespace stride::identify
