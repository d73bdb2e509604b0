#pragma once
// What `stride identify` writes: the robot override file a scene's <robot> includes
// (`<include file="robot-id.xml"/>`: <servo joint ...> and <imu gyro_bias>), each value with its
// 95 % interval and the fit's per-joint residuals in comments; the report lines it prints; and
// the logged / identified / nominal traces as CSV for plots.
#include <string>
#include <vector>

#include "console/identify/identify.hpp"

namespace stride::identify {

// The override file's text. `source`: the log it came from, for its header.
std::string override_text(const IdentifyResult& r, const std::string& source);

// One line per parameter and per joint, for the terminal.
std::vector<std::string> report_lines(const IdentifyResult& r);

// time, then per joint: logged, identified and nominal position (rad).
std::string traces_csv(const IdentifyLog& log, const IdentifyResult& r);

}  // namespace stride::identify
