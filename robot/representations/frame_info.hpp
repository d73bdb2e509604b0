#pragma once
// Written by the Runtime each frame: when this frame is, and how long the control period is.
#include <cstdint>
#include <string>
#include <vector>

#include "robot/framework/reflect.hpp"

namespace stride {

struct FrameInfo {
  double time = 0;         // link clock at sampling
  std::int64_t frame = 0;  // frames since the Runtime started, from 0
  double period = 0;       // control period of the link; modules never assume it

  static constexpr std::string_view kTypeName = "FrameInfo";
  static constexpr auto fields() {
    return std::make_tuple(field("time", &FrameInfo::time, "s"), field("frame", &FrameInfo::frame),
                           field("period", &FrameInfo::period, "s"));
  }
};

// Execution time of each module in the previous frame, in execution order.
struct ModuleTimes {
  std::vector<std::string> modules;
  std::vector<std::int64_t> ns;

  static constexpr std::string_view kTypeName = "ModuleTimes";
  static constexpr auto fields() {
    return std::make_tuple(field("modules", &ModuleTimes::modules),
                           field("ns", &ModuleTimes::ns, "ns"));
  }
};

}  // namespace stride
