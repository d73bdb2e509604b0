#pragma once
// The console keys about a controller besides its representations and parameters:
// provider:<Rep> (who writes it), override:<Rep> (the held `set` assignments) and
// debug:<request>.<value> (the latest value a debug request plotted). Read in one place for the
// console's local target and for the debug server, so a robot answers in the same words whether
// it is simulated here or reached with `connect`.
#include <optional>
#include <string>
#include <string_view>

#include "robot/framework/module.hpp"

namespace stride {

class Runtime;

bool is_controller_key(std::string_view key);
// The key's value as the console prints it; throws stride::Error (one line) naming the key.
std::string controller_value(const Runtime& rt, const std::string& key);
// A debug:X.y value as controller_value() prints it: all the digits that read back the same
// double (the module's own value, streamed or not).
std::string debug_value_text(double v);
// The switch debug_switch_name() names ("off", "on", "quiet"); nothing for any other word.
std::optional<DebugSwitch> debug_switch_named(std::string_view name);

}  // namespace stride
