#pragma once
// Reading LoLA's msgpack maps strictly: every value checked for its type, length and finiteness,
// every error one line naming the packet, the key and what was expected.
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

#include <msgpack.hpp>

namespace stride::hal::lola {

// Unpacks one msgpack object from `bytes` (all of them), with limits that keep a hostile packet
// from allocating more than a LoLA map needs. Throws stride::Error naming `what`.
msgpack::object_handle unpack_packet(std::span<const char> bytes, std::string_view what);

// Limits for msgpack::unpack: a LoLA map has at most 13 keys, arrays of at most 25 elements.
const msgpack::unpack_limit& packet_limits();

class MapReader {
 public:
  // `what` names the packet in errors ("LoLA sensor packet").
  MapReader(const msgpack::object& map, std::string_view what);
  std::size_t size() const { return map_.size; }
  // The key of entry i (a string), and its value.
  std::string_view key(std::size_t i) const;
  const msgpack::object& value(std::size_t i) const { return map_.ptr[i].val; }

  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  // Finite numbers (float32, float64 or integer) of an array of exactly out.size() elements.
  void numbers(std::size_t i, std::span<double> out) const;
  void integers(std::size_t i, std::span<std::int32_t> out) const;
  void booleans(std::size_t i, std::span<bool> out) const;
  // Views into the unpacked map: valid while its object_handle lives.
  void strings(std::size_t i, std::span<std::string_view> out) const;

 private:
  const msgpack::object_array& array(std::size_t i, std::size_t length) const;
  msgpack::object_map map_{};
  std::string_view what_;
};

}  // namespace stride::hal::lola
