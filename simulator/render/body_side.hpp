#pragma once
// Which side of the robot a link belongs to, from its name as robot makers write it: "LThigh",
// "RAnkle" (NAO), "l_hip", "left_foot", "RightArm". Pictures colour the sides apart.
#include <array>
#include <string_view>

#include "robot/framework/reflect.hpp"

namespace stride::render {

enum class BodySide { Centre, Left, Right };

BodySide side_of_link(std::string_view name);

}  // namespace stride::render

template <>
struct stride::EnumNames<stride::render::BodySide> {
  static constexpr std::string_view type_name = "BodySide";
  static constexpr std::array<std::string_view, 3> names{"centre", "left", "right"};
};
