#pragma once
// Msgpack written byte by byte from the format's specification, independent of msgpack-cxx: the
// tests build LoLA packets with it exactly as nao-facts.md describes them.
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>

namespace stride::test {

struct MsgpackBytes {
  std::string b;

  void byte(unsigned v) { b.push_back(static_cast<char>(v & 0xff)); }
  void be16(unsigned v) {
    byte(v >> 8);
    byte(v);
  }
  void fixmap(unsigned n) { byte(0x80 | n); }
  void fixarray(unsigned n) { byte(0x90 | n); }
  void array16(unsigned n) {
    byte(0xdc);
    be16(n);
  }
  void array(unsigned n) { n < 16 ? fixarray(n) : array16(n); }
  void fixstr(std::string_view s) {
    byte(0xa0 | static_cast<unsigned>(s.size()));
    b.append(s);
  }
  void float32(float f) {
    byte(0xca);
    const auto u = std::bit_cast<std::uint32_t>(f);
    for (int shift = 24; shift >= 0; shift -= 8) byte(u >> shift);
  }
  void float64(double d) {
    byte(0xcb);
    const auto u = std::bit_cast<std::uint64_t>(d);
    for (int shift = 56; shift >= 0; shift -= 8) byte(static_cast<unsigned>(u >> shift));
  }
  void fixint(unsigned v) { byte(v & 0x7f); }
  void boolean(bool v) { byte(v ? 0xc3 : 0xc2); }
  void nil() { byte(0xc0); }
};

}  // namespace stride::test
