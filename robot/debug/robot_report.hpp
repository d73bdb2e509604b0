#pragma once
// A robot's `report` over the debug server (text or JSON) and the `list` reply, from what the
// loop read between frames plus the server's own counts.
#include <string>

#include "robot/debug/exchange.hpp"
#include "robot/debug/server_options.hpp"

namespace stride::debug {

std::string robot_report_text(const RobotState& s, const ServerStats& stats);
std::string robot_report_json(const RobotState& s, const ServerStats& stats);
// The fields of a `list` reply after t/id/ok.
void write_list_fields(class MapWriter& w, const RobotState& s);

}  // namespace stride::debug
