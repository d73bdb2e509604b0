#pragma once
// What the Runtime's command guard changed before commands reached the link (robot/runtime/
// command_guard.hpp), summed since the Runtime started; written every frame by the Runtime.
#include <cstdint>
#include <string>

#include "robot/framework/reflect.hpp"

namespace stride {

struct CommandSafety {
  std::int64_t clamped_positions = 0;  // joint positions moved onto a joint limit (joint-frames)
  std::int64_t clamped_stiffness = 0;  // stiffness moved into 0..1 (joint-frames)
  std::int64_t nonfinite_held = 0;     // NaN/inf commands replaced by the joint's last valid one
  std::int64_t held_frames = 0;        // frames that sent the last safe command (a module failed)
  std::int64_t module_errors = 0;      // exceptions caught from modules
  std::string first_error;             // "Module: message" of the first one

  static constexpr std::string_view kTypeName = "CommandSafety";
  static constexpr auto fields() {
    using C = CommandSafety;
    return std::make_tuple(field("clamped_positions", &C::clamped_positions),
                           field("clamped_stiffness", &C::clamped_stiffness),
                           field("nonfinite_held", &C::nonfinite_held),
                           field("held_frames", &C::held_frames),
                           field("module_errors", &C::module_errors),
                           field("first_error", &C::first_error));
  }
};

}  // namespace stride
