#pragma once
// What one run sends back: its id, whether it ran to the end, why not, and its record columns as
// text (numbers in the shortest form that reads back to the same bits). A reflected struct, so it
// crosses process and MPI boundaries as the framework's binary encoding, never as raw memory.
#include <cstdint>
#include <string>
#include <vector>

#include "robot/framework/binary.hpp"

namespace stride::sweep {

struct RunRow {
  STRIDE_FIELDS(RunRow);
  STRIDE_FIELD(std::int64_t, run) = -1;
  STRIDE_FIELD(bool, ok) = false;
  STRIDE_FIELD(std::string, reason);              // why it failed (one line)
  STRIDE_FIELD(std::vector<std::string>, cells);  // record columns, in order (empty when it failed)
  STRIDE_FIELD(std::string, trace_csv);           // the run's trace, when the sweep asked for one
  STRIDE_FIELD(double, seconds, "s") = 0;         // wall time of the run where it ran
  STRIDE_FIELD(std::int32_t, attempts) = 1;       // 2: its first worker died

  static constexpr std::string_view kTypeName = "RunRow";
};

inline std::string encode_row(const RunRow& row) {
  return to_binary(row);
}
// Throws stride::Error on bytes that are not exactly one RunRow.
inline RunRow decode_row(std::string_view bytes) {
  RunRow row;
  from_binary(row, bytes);
  return row;
}

}  // namespace stride::sweep
