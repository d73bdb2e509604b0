#pragma once
// One log fuzz input: the bytes of a log file (either format). The reader either refuses it with
// a stride::Error or yields frames whose every representation decodes to text or is refused with
// a stride::Error; anything else (another exception, a sanitizer report) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "robot/core/error.hpp"
#include "robot/runtime/log.hpp"

namespace stride::test {

// Returns how many representations decoded.
inline int read_log_fuzz_input(const std::uint8_t* data, std::size_t size) {
  int decoded = 0;
  try {
    const LogReader log =
        LogReader::from_bytes(std::string(reinterpret_cast<const char*>(data), size), "fuzz.log");
    log.summary();
    for (std::size_t f = 0; f < log.frame_count() && f < 64; ++f) {
      if (!log.readable(f)) continue;
      for (const auto& t : log.types()) try {
          log.text(f, t.name);
          ++decoded;
        } catch (const Error&) {
        }
    }
  } catch (const Error&) {
  }
  return decoded;
}

}  // namespace stride::test
