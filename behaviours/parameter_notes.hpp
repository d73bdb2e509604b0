#pragma once
// Module parameters that their ranges accept but no NAO could use: a 10 ms stride, swing-leg gains
// that ask for a thousand times the motors' torque, balance gains a 10 ms control loop cannot
// follow. They are not refused (a study may probe them on purpose) but flagged, one line each,
// so an absurd value typed by mistake does not pass as a result.
#include <string>
#include <vector>

#include "robot/framework/slot.hpp"

namespace stride::behaviours {

// Notes on `parameters` (the parameter struct of a shipped module named `module`), each starting
// with the module's name, e.g. "PatternWalk: T_stride = 0.01 s: no NAO strides that fast (...)";
// empty when every value is plausible or the module has no such check.
std::vector<std::string> parameter_notes(const std::string& module, const Slot& parameters);

}  // namespace stride::behaviours
