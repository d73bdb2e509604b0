#pragma once
// The <physics solver="..."> names, read by the scene parser and written in run reports.
#include <array>
#include <string_view>

#include "robot/framework/reflect.hpp"
#include "simulator/scene/scene_description.hpp"

template <>
struct stride::EnumNames<stride::sim::PhysicsSettings::Solver> {
  static constexpr std::string_view type_name = "Solver";
  static constexpr std::array<std::string_view, 3> names{"exact", "iterative", "cg"};
};
