#pragma once
// Which side of the robot a link belongs to, from its name as robot makers write it: "LThigh",
// "RAnkle" (NAO), "l_hip", "left_foot", "RightArm". Pictures colour the sides apart.
#include <string_view>

namespace stride::render {

enum class BodySide { Centre, Left, Right };

BodySide side_of_link(std::string_view name);

}  // namespace stride::render
