#pragma once
// Debug-server framing: every message is a 4-byte big-endian payload length, then that many bytes
// of msgpack. A reader never buffers more than one message over its limit.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace stride::debug {

inline constexpr std::size_t kLengthPrefix = 4;

// Appends `payload` with its length prefix to `out`.
void append_frame(std::string& out, std::string_view payload);

// Splits a received byte stream into payloads.
class FrameReader {
 public:
  explicit FrameReader(std::size_t max_payload) : max_payload_(max_payload) {}

  void feed(std::string_view bytes) { buffer_.append(bytes); }
  // The next complete payload, or nothing until more bytes arrive. Throws stride::Error as soon
  // as a length prefix announces more than the limit (before any of that payload is buffered).
  std::optional<std::string> next();
  std::size_t buffered() const { return buffer_.size() - start_; }
  std::size_t max_payload() const { return max_payload_; }

 private:
  std::size_t max_payload_;
  std::string buffer_;
  std::size_t start_ = 0;  // consumed bytes at the front of buffer_
};

}  // namespace stride::debug
