#pragma once
// What the Runtime's command guard changed before commands reached the link (robot/runtime/
// command_guard.hpp), summed since the Runtime started; written every frame by the Runtime.
#include <cstdint>
#include <string>

#include "robot/framework/reflect.hpp"

namespace stride {

struct CommandSafety {
  STRIDE_FIELDS(CommandSafety);
  // joint positions moved onto a joint limit (joint-frames)
  STRIDE_FIELD(std::int64_t, clamped_positions) = 0;
  STRIDE_FIELD(std::int64_t, clamped_stiffness) = 0;  // stiffness moved into 0..1 (joint-frames)
  // NaN/inf commands replaced by the joint's last valid one
  STRIDE_FIELD(std::int64_t, nonfinite_held) = 0;
  // frames that sent the last safe command (a module failed)
  STRIDE_FIELD(std::int64_t, held_frames) = 0;
  STRIDE_FIELD(std::int64_t, module_errors) = 0;  // exceptions caught from modules
  STRIDE_FIELD(std::string, first_error);         // "Module: message" of the first one

  static constexpr std::string_view kTypeName = "CommandSafety";
};

}  // namespace stride
