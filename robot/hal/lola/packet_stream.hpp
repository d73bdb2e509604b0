#pragma once
// Packets out of a stream socket: LoLA writes one msgpack map per frame with no length prefix,
// so the bytes received are cut where each complete msgpack value ends.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <msgpack.hpp>

namespace stride::hal::lola {

class PacketStream {
 public:
  // Space for up to `n` more received bytes; commit() says how many arrived.
  std::span<char> reserve(std::size_t n);
  void commit(std::size_t n) { end_ += n; }
  void append(std::span<const char> bytes);

  enum class Result { Packet, NeedMore, Malformed };
  // The next complete map: Packet (its bytes, valid until the next call that changes the
  // stream), NeedMore, or Malformed (`error` says why: not a map, not msgpack, too long; every
  // buffered byte is dropped, so the stream starts again with the next write of the peer).
  Result next(std::span<const char>& packet, std::string& error);

  std::size_t buffered() const { return end_ - begin_; }
  void clear() { begin_ = end_ = 0; }

 private:
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0;
};

}  // namespace stride::hal::lola
