#pragma once
// Writing LoLA's msgpack: a msgpack::packer stream that appends to a std::string (reserved once,
// reused every frame), and the two forms LoLA insists on that msgpack-cxx would shorten.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <msgpack.hpp>

namespace stride::hal::lola {

struct StringSink {
  std::string& out;
  void write(const char* data, std::size_t size) { out.append(data, size); }
};

using Packer = msgpack::packer<StringSink>;

// Always float32 (0xca + 4 bytes big-endian): msgpack-cxx's pack_float writes a whole-numbered
// value as an integer, and LoLA's packets carry every value as float32 (nao-facts.md).
inline void pack_float32(Packer& p, float v) {
  const auto bits = std::bit_cast<std::uint32_t>(v);
  const char bytes[5] = {'\xca', static_cast<char>(bits >> 24), static_cast<char>(bits >> 16),
                         static_cast<char>(bits >> 8), static_cast<char>(bits)};
  p.pack_bin_body(bytes, 5);  // raw bytes: pack_bin_body writes them unchanged
}

// A string as fixstr (every LoLA key and RobotConfig value is shorter than 32 bytes).
inline void pack_key(Packer& p, std::string_view key) {
  p.pack_str(static_cast<std::uint32_t>(key.size()));
  p.pack_str_body(key.data(), static_cast<std::uint32_t>(key.size()));
}

}  // namespace stride::hal::lola
