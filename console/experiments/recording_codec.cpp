#include "console/experiments/recording_codec.hpp"

#include <cstdint>
#include <type_traits>

#include "robot/core/error.hpp"
#include "robot/framework/byte_io.hpp"

namespace stride::experiments {
namespace {

static_assert(std::is_trivially_copyable_v<sim::WalkMetricsResult>);

// A count read back, checked against the bytes left so that bad data cannot ask for gigabytes.
std::size_t count(ByteReader& in, std::size_t item_bytes) {
  const auto n = in.get<std::uint64_t>();
  if (n > in.remaining() / item_bytes)
    throw Error("walk recording: a count of " + std::to_string(n) + " exceeds the bytes left");
  return n;
}

}  // namespace

std::string encode_recording(const WalkRecording& r) {
  std::string bytes;
  ByteWriter out(bytes);
  out.put(std::uint64_t{r.trace.columns.size()});
  for (const auto& c : r.trace.columns) out.put_string(c);
  out.put(std::uint64_t{r.trace.rows.size()});
  for (const auto& row : r.trace.rows) {
    out.put(std::uint64_t{row.size()});
    for (double v : row) out.put(v);
  }
  out.put(r.metrics);
  out.put(r.walk_duration);
  out.put(r.period);
  out.put_string(r.walk_module);
  return bytes;
}

WalkRecording decode_recording(std::string_view bytes) {
  ByteReader in(bytes);
  WalkRecording r;
  r.trace.columns.resize(count(in, sizeof(std::uint32_t)));
  for (auto& c : r.trace.columns) c = in.get_string();
  r.trace.rows.resize(count(in, sizeof(std::uint64_t)));
  for (auto& row : r.trace.rows) {
    row.resize(count(in, sizeof(double)));
    for (double& v : row) v = in.get<double>();
  }
  r.metrics = in.get<sim::WalkMetricsResult>();
  r.walk_duration = in.get<double>();
  r.period = in.get<double>();
  r.walk_module = in.get_string();
  if (in.remaining() != 0)
    throw Error("walk recording: " + std::to_string(in.remaining()) + " bytes after the end");
  return r;
}

}  // namespace stride::experiments
