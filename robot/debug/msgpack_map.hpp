#pragma once
// msgpack for the debug protocol: every message is one map with string keys. MapView reads a
// decoded map with one-line errors naming the field (a str that is not UTF-8 is such an error);
// MapWriter packs one, its strs always UTF-8. Unknown keys are
// ignored, so consoles and robots of other revisions can add fields.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <msgpack.hpp>

namespace stride::debug {

// Limits for decoding hostile input: no count may make the decoder allocate more than the
// message itself could describe.
struct DecodeLimits {
  std::size_t array = 4096, map = 64, str = 1 << 20, bin = 1 << 20, depth = 6;
};

// Decodes exactly one msgpack object filling all of `payload`; throws stride::Error.
msgpack::object_handle decode_msgpack(std::string_view payload, const DecodeLimits& limits);

class MapView {
 public:
  // `what` names the message in errors, e.g. "request 'get'".
  MapView(const msgpack::object& o, std::string what);

  bool has(std::string_view key) const { return find(key) != nullptr; }
  std::string text(std::string_view key) const;
  std::string text_or(std::string_view key, std::string fallback) const;
  std::string bytes(std::string_view key) const;
  std::uint64_t unsigned_integer(std::string_view key, std::uint64_t max) const;
  std::uint64_t unsigned_or(std::string_view key, std::uint64_t fallback, std::uint64_t max) const;
  std::int64_t integer(std::string_view key) const;
  double number(std::string_view key) const;
  bool boolean(std::string_view key) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  std::vector<std::string> texts(std::string_view key) const;
  std::vector<std::string> byte_list(std::string_view key) const;
  std::vector<bool> booleans(std::string_view key) const;
  std::vector<double> numbers(std::string_view key) const;
  std::vector<std::vector<std::string>> text_lists(std::string_view key) const;

 private:
  const msgpack::object* find(std::string_view key) const;
  const msgpack::object& need(std::string_view key) const;
  std::string utf8_of(std::string_view key, const msgpack::object& str) const;  // or throws
  [[noreturn]] void wrong(std::string_view key, const char* expected,
                          const msgpack::object& got) const;
  const msgpack::object& map_;
  std::string what_;
};

// Packs one map: key/value pairs in order, then finish() gives the encoded message.
class MapWriter {
 public:
  MapWriter() : sink_{body_}, packer_(sink_) {}
  MapWriter(const MapWriter&) = delete;
  MapWriter& operator=(const MapWriter&) = delete;
  std::string finish() const;
  MapWriter& text(std::string_view key, std::string_view value);
  MapWriter& bytes(std::string_view key, std::string_view value);
  MapWriter& unsigned_integer(std::string_view key, std::uint64_t value);
  MapWriter& integer(std::string_view key, std::int64_t value);
  MapWriter& number(std::string_view key, double value);
  MapWriter& boolean(std::string_view key, bool value);
  MapWriter& texts(std::string_view key, const std::vector<std::string>& values);
  MapWriter& byte_list(std::string_view key, const std::vector<std::string>& values);
  MapWriter& booleans(std::string_view key, const std::vector<bool>& values);
  MapWriter& numbers(std::string_view key, const std::vector<double>& values);
  MapWriter& text_lists(std::string_view key, const std::vector<std::vector<std::string>>& values);

 private:
  struct Sink {
    std::string& s;
    void write(const char* p, std::size_t n) { s.append(p, n); }
  };
  void key(std::string_view k);
  void str(std::string_view v);  // always UTF-8: bytes that are not are escaped
  std::string body_;
  std::uint32_t entries_ = 0;
  Sink sink_;
  msgpack::packer<Sink> packer_;
};

}  // namespace stride::debug
