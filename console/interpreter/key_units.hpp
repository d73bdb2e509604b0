#pragma once
// The unit of a console key's value, for axis labels: from the field list's units for
// representation:/module: keys, from the simulator's conventions for robot.* and sim.* keys.
#include <string>
#include <string_view>

namespace stride {
struct TypeDesc;
}

namespace stride::console {

class RobotTarget;

// The unit of the field `path` ("position[10]", "com.x") of a described type; "" if none.
std::string unit_of_path(const TypeDesc& type, std::string_view path);

// The unit of `key`'s value ("rad", "m", "s"), "" when it has none or it is unknown.
std::string unit_of_key(RobotTarget& target, const std::string& key);

// The unit of a debug value by its name ("torso_pitch": rad, "zmp_x": m), "" if it does not say.
std::string unit_of_debug_value(std::string_view name);

}  // namespace stride::console
