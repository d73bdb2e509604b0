#pragma once
// One fuzz input for `stride identify`'s own parsers: an input starting with "STRDLOG" is a log
// read as identify reads it (checks of integrity, representations, period, tilt); any other is
// text whose first line is a --params list and whose second a --joints list. Any outcome but
// success or a one-line stride::Error is a bug (the caller sees other exceptions).
#include <cstddef>
#include <cstdint>
#include <string>

#include "console/identify/identify_log.hpp"
#include "console/identify/identify_params.hpp"
#include "robot/core/error.hpp"
#include "robot/runtime/log.hpp"

namespace stride::test {

// Returns the error message, or "" when the input was accepted.
inline std::string identify_fuzz_input(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    if (text.starts_with("STRDLOG")) {
      identify::read_identify_log(LogReader::from_bytes(text, "fuzz.log"), "fuzz.log");
    } else {
      const auto nl = text.find('\n');
      identify::parse_param_list(text.substr(0, nl));
      identify::parse_joint_list(nl == std::string::npos ? "" : text.substr(nl + 1));
    }
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace stride::test
