#pragma once
// A type description (robot/framework/type_desc.hpp) as the `tree` message's <typedesc>.
#include "console/view/view_json.hpp"
#include "robot/framework/type_desc.hpp"

namespace stride::view {

Json type_desc_json(const TypeDesc& d, const std::string& unit = "");

}  // namespace stride::view
