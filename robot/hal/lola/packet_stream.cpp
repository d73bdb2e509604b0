#include "robot/hal/lola/packet_stream.hpp"

#include <cstdio>
#include <cstring>

#include "robot/hal/lola/lola_protocol.hpp"
#include "robot/hal/lola/msgpack_fields.hpp"

namespace stride::hal::lola {

std::span<char> PacketStream::reserve(std::size_t n) {
  if (begin_ > 0) {  // move the unread bytes to the front first
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (buffer_.size() < end_ + n) buffer_.resize(end_ + n);
  return {buffer_.data() + end_, n};
}

void PacketStream::append(std::span<const char> bytes) {
  const auto space = reserve(bytes.size());
  std::memcpy(space.data(), bytes.data(), bytes.size());
  commit(bytes.size());
}

PacketStream::Result PacketStream::next(std::span<const char>& packet, std::string& error) {
  if (begin_ == end_) return Result::NeedMore;
  // Every LoLA packet is one map: anything else is the middle of a packet (the stream lost its
  // place), dropped whole rather than counted value by value as packets.
  const auto lead = static_cast<unsigned char>(buffer_[begin_]);
  if ((lead & 0xf0) != 0x80 && lead != 0xde && lead != 0xdf) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02x", lead);
    error = std::to_string(end_ - begin_) + " bytes that do not start a msgpack map (first byte " +
            hex + ")";
    clear();
    return Result::Malformed;
  }
  std::size_t offset = begin_;
  try {
    // Only the extent is wanted here; the caller decodes the packet it keeps.
    msgpack::unpack(buffer_.data(), end_, offset, nullptr, nullptr, packet_limits());
  } catch (const msgpack::insufficient_bytes&) {
    if (end_ - begin_ <= kMaxPacketSize) return Result::NeedMore;
    error = std::to_string(end_ - begin_) + " bytes without the end of a msgpack value (at most " +
            std::to_string(kMaxPacketSize) + ")";
    clear();
    return Result::Malformed;
  } catch (const std::exception& e) {
    error = std::string("not a LoLA msgpack map (") + e.what() + ")";
    clear();
    return Result::Malformed;
  }
  packet = {buffer_.data() + begin_, offset - begin_};
  begin_ = offset;
  if (begin_ == end_) begin_ = end_ = 0;  // the packet's bytes stay in place until next reserve()
  return Result::Packet;
}

}  // namespace stride::hal::lola
