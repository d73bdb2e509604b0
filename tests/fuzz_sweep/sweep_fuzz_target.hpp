#pragma once
// One fuzz input for the sweep engine's decoders: the first byte picks the sweep-file parser (and
// the checks that compile its keys, expressions and tallies without loading scenes), the CSV
// line reader of --resume, or the RunRow decoder of worker messages; the rest is the input. Any
// outcome but success or a stride::Error is a bug (the caller sees other exceptions).
#include <cstddef>
#include <cstdint>
#include <string>

#include "console/sweep/csv_line.hpp"
#include "console/sweep/run_row.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "console/sweep/tally.hpp"
#include "robot/core/error.hpp"

namespace stride::test {

// Returns the error message, or "" when the input was accepted.
inline std::string sweep_fuzz_input(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return "";
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    switch (data[0] % 3) {
      case 0: {
        const sweep::Sweep s(sweep::parse_sweep_text(text, "/nonexistent/fuzz.sweep.xml"), false);
        const sweep::Tallies t(s);
        break;
      }
      case 1:
        sweep::parse_csv_line(text);
        break;
      default:
        sweep::decode_row(text);
        break;
    }
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace stride::test
