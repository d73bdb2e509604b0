#include "robot/debug/msgpack_map.hpp"

#include <optional>

#include <exception>

#include "robot/core/error.hpp"
#include "robot/core/msgpack_type_name.hpp"
#include "robot/core/one_line.hpp"
#include "robot/core/utf8.hpp"

namespace stride::debug {

msgpack::object_handle decode_msgpack(std::string_view payload, const DecodeLimits& l) {
  std::size_t offset = 0;
  msgpack::object_handle h;
  try {
    const msgpack::unpack_limit limit(l.array, l.map, l.str, l.bin, 0, l.depth);
    h = msgpack::unpack(payload.data(), payload.size(), offset, nullptr, nullptr, limit);
  } catch (const std::bad_alloc&) {
    throw Error("msgpack: out of memory decoding " + std::to_string(payload.size()) + " bytes");
  } catch (const std::exception& e) {
    throw Error(std::string("msgpack: ") + e.what() + " (" + std::to_string(payload.size()) +
                " bytes)");
  }
  if (offset != payload.size())
    throw Error("msgpack: " + std::to_string(payload.size() - offset) + " bytes after the message");
  return h;
}

MapView::MapView(const msgpack::object& o, std::string what) : map_(o), what_(std::move(what)) {
  if (o.type != msgpack::type::MAP)
    throw Error(what_ + ": expected a map, got " + std::string(msgpack_type_name(o.type)));
}

const msgpack::object* MapView::find(std::string_view key) const {
  for (std::uint32_t i = 0; i < map_.via.map.size; ++i) {
    const auto& kv = map_.via.map.ptr[i];
    if (kv.key.type == msgpack::type::STR &&
        std::string_view(kv.key.via.str.ptr, kv.key.via.str.size) == key)
      return &kv.val;
  }
  return nullptr;
}

const msgpack::object& MapView::need(std::string_view key) const {
  if (const auto* o = find(key)) return *o;
  throw Error(what_ + ": field '" + std::string(key) + "' is missing");
}

void MapView::wrong(std::string_view key, const char* expected, const msgpack::object& got) const {
  throw Error(what_ + ": field '" + std::string(key) + "': expected " + expected + ", got " +
              msgpack_type_name(got.type));
}

std::string MapView::text(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::STR) wrong(key, "a string", o);
  return utf8_of(key, o);
}

std::string MapView::utf8_of(std::string_view key, const msgpack::object& o) const {
  std::string s(o.via.str.ptr, o.via.str.size);
  if (!valid_utf8(s))
    throw Error(what_ + ": field '" + std::string(key) + "': expected UTF-8 text, got '" +
                one_line(s, 60) + "'");
  return s;
}

std::string MapView::text_or(std::string_view key, std::string fallback) const {
  return has(key) ? text(key) : fallback;
}

std::string MapView::bytes(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::BIN) wrong(key, "binary", o);
  return std::string(o.via.bin.ptr, o.via.bin.size);
}

std::uint64_t MapView::unsigned_integer(std::string_view key, std::uint64_t max) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::POSITIVE_INTEGER) wrong(key, "an unsigned integer", o);
  if (o.via.u64 > max)
    throw Error(what_ + ": field '" + std::string(key) + "': " + std::to_string(o.via.u64) +
                " is over the limit " + std::to_string(max));
  return o.via.u64;
}

std::uint64_t MapView::unsigned_or(std::string_view key, std::uint64_t fallback,
                                   std::uint64_t max) const {
  return has(key) ? unsigned_integer(key, max) : fallback;
}

std::int64_t MapView::integer(std::string_view key) const {
  const auto& o = need(key);
  if (o.type == msgpack::type::NEGATIVE_INTEGER) return o.via.i64;
  if (o.type != msgpack::type::POSITIVE_INTEGER || o.via.u64 > INT64_MAX)
    wrong(key, "an integer", o);
  return static_cast<std::int64_t>(o.via.u64);
}

namespace {
// A number of any msgpack kind (msgpack-c packs a double without a fraction as an integer).
std::optional<double> number_in(const msgpack::object& o) {
  if (o.type == msgpack::type::FLOAT32 || o.type == msgpack::type::FLOAT64) return o.via.f64;
  if (o.type == msgpack::type::POSITIVE_INTEGER) return static_cast<double>(o.via.u64);
  if (o.type == msgpack::type::NEGATIVE_INTEGER) return static_cast<double>(o.via.i64);
  return std::nullopt;
}
}  // namespace

double MapView::number(std::string_view key) const {
  const auto& o = need(key);
  if (const auto v = number_in(o)) return *v;
  wrong(key, "a number", o);
}

bool MapView::boolean(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::BOOLEAN) wrong(key, "a boolean", o);
  return o.via.boolean;
}

bool MapView::boolean_or(std::string_view key, bool fallback) const {
  return has(key) ? boolean(key) : fallback;
}

namespace {
template <class F>
void each_item(const msgpack::object& list, F&& item) {
  for (std::uint32_t i = 0; i < list.via.array.size; ++i) item(list.via.array.ptr[i]);
}
}  // namespace

std::vector<std::string> MapView::texts(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::ARRAY) wrong(key, "an array of strings", o);
  std::vector<std::string> out;
  each_item(o, [&](const msgpack::object& e) {
    if (e.type != msgpack::type::STR) wrong(key, "an array of strings", e);
    out.push_back(utf8_of(key, e));
  });
  return out;
}

std::vector<std::string> MapView::byte_list(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::ARRAY) wrong(key, "an array of binaries", o);
  std::vector<std::string> out;
  each_item(o, [&](const msgpack::object& e) {
    if (e.type != msgpack::type::BIN) wrong(key, "an array of binaries", e);
    out.emplace_back(e.via.bin.ptr, e.via.bin.size);
  });
  return out;
}

std::vector<bool> MapView::booleans(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::ARRAY) wrong(key, "an array of booleans", o);
  std::vector<bool> out;
  each_item(o, [&](const msgpack::object& e) {
    if (e.type != msgpack::type::BOOLEAN) wrong(key, "an array of booleans", e);
    out.push_back(e.via.boolean);
  });
  return out;
}

std::vector<double> MapView::numbers(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::ARRAY) wrong(key, "an array of numbers", o);
  std::vector<double> out;
  each_item(o, [&](const msgpack::object& e) {
    const auto v = number_in(e);
    if (!v) wrong(key, "an array of numbers", e);
    out.push_back(*v);
  });
  return out;
}

std::vector<std::vector<std::string>> MapView::text_lists(std::string_view key) const {
  const auto& o = need(key);
  if (o.type != msgpack::type::ARRAY) wrong(key, "an array of string arrays", o);
  std::vector<std::vector<std::string>> out;
  each_item(o, [&](const msgpack::object& list) {
    if (list.type != msgpack::type::ARRAY) wrong(key, "an array of string arrays", list);
    auto& row = out.emplace_back();
    each_item(list, [&](const msgpack::object& e) {
      if (e.type != msgpack::type::STR) wrong(key, "an array of string arrays", e);
      row.push_back(utf8_of(key, e));
    });
  });
  return out;
}

std::string MapWriter::finish() const {
  std::string out;
  Sink sink{out};
  msgpack::packer<Sink>(sink).pack_map(entries_);
  return out + body_;
}

void MapWriter::key(std::string_view k) {
  ++entries_;
  str(k);
}

void MapWriter::str(std::string_view v) {
  if (!valid_utf8(v)) return str(utf8_escaped(v));  // a peer's bytes, echoed: escaped
  packer_.pack_str(static_cast<std::uint32_t>(v.size()));
  packer_.pack_str_body(v.data(), static_cast<std::uint32_t>(v.size()));
}

MapWriter& MapWriter::text(std::string_view k, std::string_view v) {
  key(k);
  str(v);
  return *this;
}

MapWriter& MapWriter::bytes(std::string_view k, std::string_view v) {
  key(k);
  packer_.pack_bin(static_cast<std::uint32_t>(v.size()));
  packer_.pack_bin_body(v.data(), static_cast<std::uint32_t>(v.size()));
  return *this;
}

MapWriter& MapWriter::unsigned_integer(std::string_view k, std::uint64_t v) {
  key(k);
  packer_.pack_uint64(v);
  return *this;
}

MapWriter& MapWriter::integer(std::string_view k, std::int64_t v) {
  key(k);
  packer_.pack_int64(v);
  return *this;
}

MapWriter& MapWriter::number(std::string_view k, double v) {
  key(k);
  packer_.pack_double(v);
  return *this;
}

MapWriter& MapWriter::boolean(std::string_view k, bool v) {
  key(k);
  v ? packer_.pack_true() : packer_.pack_false();
  return *this;
}

MapWriter& MapWriter::texts(std::string_view k, const std::vector<std::string>& values) {
  key(k);
  packer_.pack_array(static_cast<std::uint32_t>(values.size()));
  for (const auto& v : values) str(v);
  return *this;
}

MapWriter& MapWriter::byte_list(std::string_view k, const std::vector<std::string>& values) {
  key(k);
  packer_.pack_array(static_cast<std::uint32_t>(values.size()));
  for (const auto& v : values) {
    packer_.pack_bin(static_cast<std::uint32_t>(v.size()));
    packer_.pack_bin_body(v.data(), static_cast<std::uint32_t>(v.size()));
  }
  return *this;
}

MapWriter& MapWriter::booleans(std::string_view k, const std::vector<bool>& values) {
  key(k);
  packer_.pack_array(static_cast<std::uint32_t>(values.size()));
  for (bool v : values) v ? packer_.pack_true() : packer_.pack_false();
  return *this;
}

MapWriter& MapWriter::numbers(std::string_view k, const std::vector<double>& values) {
  key(k);
  packer_.pack_array(static_cast<std::uint32_t>(values.size()));
  for (double v : values) packer_.pack_double(v);
  return *this;
}

MapWriter& MapWriter::text_lists(std::string_view k,
                                 const std::vector<std::vector<std::string>>& values) {
  key(k);
  packer_.pack_array(static_cast<std::uint32_t>(values.size()));
  for (const auto& row : values) {
    packer_.pack_array(static_cast<std::uint32_t>(row.size()));
    for (const auto& v : row) str(v);
  }
  return *this;
}

}  // namespace stride::debug
