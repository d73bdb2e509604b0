#include "console/interpreter/key_units.hpp"

#include "console/target/robot_target.hpp"
#include "robot/framework/type_desc.hpp"

namespace stride::console {

std::string unit_of_path(const TypeDesc& type, std::string_view path) {
  const TypeDesc* t = &type;
  std::string unit;
  while (!path.empty() && t) {
    if (path.front() == '[') {  // an element: the array's unit
      const std::size_t close = path.find(']');
      path.remove_prefix(close == std::string_view::npos ? path.size() : close + 1);
      t = t->element.get();
      continue;
    }
    if (path.front() == '.') path.remove_prefix(1);
    const std::size_t end = path.find_first_of(".[");
    const std::string_view name = path.substr(0, end);
    path.remove_prefix(end == std::string_view::npos ? path.size() : end);
    const TypeDesc* next = nullptr;
    for (const FieldDesc& f : t->fields)
      if (f.name == name) {
        if (!f.unit.empty()) unit = f.unit;  // the innermost unit named wins
        next = f.type.get();
      }
    if (!next && t->vector_components) return unit;  // .x .y .z of a vector keep its unit
    t = next;
  }
  return unit;
}

std::string unit_of_key(RobotTarget& target, const std::string& key) {
  if (key.starts_with("representation:") || key.starts_with("module:")) {
    const std::size_t cut = key.find_first_of(".[");
    try {
      const TypeDesc& type = target.type_of(key.substr(0, cut));
      return cut == std::string::npos ? "" : unit_of_path(type, std::string_view(key).substr(cut));
    } catch (const std::exception&) {
      return "";
    }
  }
  if (key == "sim.time") return "s";
  if (key.starts_with("robot.torso.")) {
    const std::string_view axis = std::string_view(key).substr(12);
    return axis == "x" || axis == "y" || axis == "z" ? "m" : "rad";
  }
  if (key.starts_with("robot.com.")) return "m";
  if (key.starts_with("debug:")) return unit_of_debug_value(key.substr(key.rfind('.') + 1));
  return "";
}

// The modules' debug values carry no field list, so their names say the unit: angles and their
// rates by name, positions (ZMP, CoP, CoM, x/y/z) in metres.
std::string unit_of_debug_value(std::string_view name) {
  auto has = [&](std::string_view part) { return name.find(part) != std::string_view::npos; };
  const bool angle = has("pitch") || has("roll") || has("yaw") || has("angle") || has("theta");
  if (angle) return has("rate") || has("velocity") ? "rad/s" : "rad";
  if (has("zmp") || has("cop") || has("com") || name == "error" || name.ends_with("_x") ||
      name.ends_with("_y") || name.ends_with("_z"))
    return "m";
  return "";
}

}  // namespace stride::console
