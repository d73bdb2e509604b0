#pragma once
// The view's WebSocket message decoder on arbitrary bytes: a typed request or one stride::Error
// line; returns that line (empty when the input decoded).
#include <cstddef>
#include <cstdint>
#include <string>

#include "console/view/view_message.hpp"
#include "robot/core/error.hpp"

namespace stride::test {

inline std::string fuzz_view_input(const std::uint8_t* data, std::size_t size) {
  try {
    stride::view::decode_view_message(std::string_view(reinterpret_cast<const char*>(data), size));
    return "";
  } catch (const stride::Error& e) {
    return e.what();
  }
}

}  // namespace stride::test
