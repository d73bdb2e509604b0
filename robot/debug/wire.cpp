#include "robot/debug/wire.hpp"

#include "robot/core/error.hpp"

namespace stride::debug {

void append_frame(std::string& out, std::string_view payload) {
  if (payload.size() > 0xffffffffu)
    throw Error("message of " + std::to_string(payload.size()) +
                " bytes cannot be framed (4-byte length)");
  const auto n = static_cast<std::uint32_t>(payload.size());
  const char prefix[kLengthPrefix] = {static_cast<char>(n >> 24), static_cast<char>(n >> 16),
                                      static_cast<char>(n >> 8), static_cast<char>(n)};
  out.append(prefix, kLengthPrefix);
  out.append(payload);
}

std::optional<std::string> FrameReader::next() {
  if (buffered() < kLengthPrefix) return std::nullopt;
  const auto* p = reinterpret_cast<const unsigned char*>(buffer_.data() + start_);
  const std::uint64_t n = (std::uint64_t{p[0]} << 24) | (std::uint64_t{p[1]} << 16) |
                          (std::uint64_t{p[2]} << 8) | std::uint64_t{p[3]};
  if (n > max_payload_)
    throw Error("message of " + std::to_string(n) + " bytes announced, over the " +
                std::to_string(max_payload_) + "-byte limit");
  if (buffered() < kLengthPrefix + n) return std::nullopt;
  std::string payload = buffer_.substr(start_ + kLengthPrefix, n);
  start_ += kLengthPrefix + n;
  if (start_ == buffer_.size()) {
    buffer_.clear();
    start_ = 0;
  } else if (start_ > 65536 && start_ * 2 > buffer_.size()) {
    buffer_.erase(0, start_);  // keep the consumed front from growing without bound
    start_ = 0;
  }
  return payload;
}

}  // namespace stride::debug
