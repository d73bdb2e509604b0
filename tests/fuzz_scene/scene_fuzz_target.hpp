#pragma once
// One fuzz input: the first byte picks the parser (bit 0: URDF, else bit 1: a `stride converge`
// physics setting, else scene XML), the rest is the text.
// Any outcome but a stride::Error or success is a bug (the caller sees other exceptions).
#include <cstddef>
#include <cstdint>
#include <string>

#include "robot/core/error.hpp"
#include "robot/model/urdf_loader.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::test {

// Returns the error message, or "" when the text parsed.
inline std::string parse_fuzz_input(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return "";
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] & 1)
      model::parse_urdf(text, "fuzz.urdf");
    else if (data[0] & 2)
      sim::parse_physics_setting(text);
    else
      sim::parse_scene_text(text, "/nonexistent/fuzz.xml");  // includes resolve to nothing
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace stride::test
