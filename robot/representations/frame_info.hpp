#pragma once
// Written by the Runtime each frame: when this frame is, and how long the control period is.
#include <cstdint>
#include <string>
#include <vector>

#include "robot/framework/reflect.hpp"

namespace stride {

struct FrameInfo {
  STRIDE_FIELDS(FrameInfo);
  STRIDE_FIELD(double, time, "s") = 0;    // link clock at sampling
  STRIDE_FIELD(std::int64_t, frame) = 0;  // frames since the Runtime started, from 0
  // control period of the link; modules never assume it
  STRIDE_FIELD(double, period, "s") = 0;

  static constexpr std::string_view kTypeName = "FrameInfo";
};

// Execution time of each module in the previous frame, in execution order.
struct ModuleTimes {
  STRIDE_FIELDS(ModuleTimes);
  STRIDE_FIELD(std::vector<std::string>, modules);
  STRIDE_FIELD(std::vector<std::int64_t>, ns, "ns");

  static constexpr std::string_view kTypeName = "ModuleTimes";
};

}  // namespace stride
