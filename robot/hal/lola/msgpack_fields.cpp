#include "robot/hal/lola/msgpack_fields.hpp"

#include <cmath>
#include <limits>

#include "robot/core/error.hpp"
#include "robot/core/msgpack_type_name.hpp"

namespace stride::hal::lola {

const msgpack::unpack_limit& packet_limits() {
  // array, map, str, bin, ext elements/bytes; nesting depth (map -> array -> element).
  static const msgpack::unpack_limit limits(64, 32, 256, 0, 0, 3);
  return limits;
}

msgpack::object_handle unpack_packet(std::span<const char> bytes, std::string_view what) {
  std::size_t offset = 0;
  msgpack::object_handle handle;
  try {
    handle = msgpack::unpack(bytes.data(), bytes.size(), offset, nullptr, nullptr, packet_limits());
  } catch (const msgpack::insufficient_bytes&) {
    throw Error(std::string(what) + ": " + std::to_string(bytes.size()) +
                " bytes end inside a msgpack value");
  } catch (const std::exception& e) {
    throw Error(std::string(what) + ": not msgpack a LoLA map can be (" + e.what() + ")");
  }
  if (offset != bytes.size())
    throw Error(std::string(what) + ": " + std::to_string(bytes.size() - offset) +
                " bytes after the map");
  return handle;
}

MapReader::MapReader(const msgpack::object& map, std::string_view what) : what_(what) {
  if (map.type != msgpack::type::MAP)
    throw Error(std::string(what) + ": expected a map, got " + msgpack_type_name(map.type));
  map_ = map.via.map;
}

std::string_view MapReader::key(std::size_t i) const {
  const msgpack::object& k = map_.ptr[i].key;
  if (k.type != msgpack::type::STR)
    throw Error(std::string(what_) + ": entry " + std::to_string(i) +
                ": expected a string key, got " + msgpack_type_name(k.type));
  return {k.via.str.ptr, k.via.str.size};
}

void MapReader::fail(std::string_view key, const std::string& message) const {
  throw Error(std::string(what_) + ": " + std::string(key) + ": " + message);
}

const msgpack::object_array& MapReader::array(std::size_t i, std::size_t length) const {
  const msgpack::object& v = value(i);
  if (v.type != msgpack::type::ARRAY)
    fail(key(i), std::string("expected an array of ") + std::to_string(length) + ", got " +
                     msgpack_type_name(v.type));
  if (v.via.array.size != length)
    fail(key(i), "expected " + std::to_string(length) + " elements, got " +
                     std::to_string(v.via.array.size));
  return v.via.array;
}

void MapReader::numbers(std::size_t i, std::span<double> out) const {
  const auto& a = array(i, out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const msgpack::object& e = a.ptr[k];
    double v = 0;
    if (e.type == msgpack::type::FLOAT32 || e.type == msgpack::type::FLOAT64)
      v = e.via.f64;
    else if (e.type == msgpack::type::POSITIVE_INTEGER)
      v = static_cast<double>(e.via.u64);
    else if (e.type == msgpack::type::NEGATIVE_INTEGER)
      v = static_cast<double>(e.via.i64);
    else
      fail(key(i),
           "[" + std::to_string(k) + "]: expected a number, got " + msgpack_type_name(e.type));
    if (!std::isfinite(v))
      fail(key(i),
           "[" + std::to_string(k) + "]: expected a finite number, got " + std::to_string(v));
    out[k] = v;
  }
}

void MapReader::integers(std::size_t i, std::span<std::int32_t> out) const {
  const auto& a = array(i, out.size());
  constexpr auto kMax = std::numeric_limits<std::int32_t>::max();
  for (std::size_t k = 0; k < out.size(); ++k) {
    const msgpack::object& e = a.ptr[k];
    if (e.type == msgpack::type::POSITIVE_INTEGER && e.via.u64 <= static_cast<std::uint64_t>(kMax))
      out[k] = static_cast<std::int32_t>(e.via.u64);
    else if (e.type == msgpack::type::NEGATIVE_INTEGER && e.via.i64 >= -kMax)
      out[k] = static_cast<std::int32_t>(e.via.i64);
    else
      fail(key(i), "[" + std::to_string(k) + "]: expected a 32-bit integer, got " +
                       msgpack_type_name(e.type));
  }
}

void MapReader::booleans(std::size_t i, std::span<bool> out) const {
  const auto& a = array(i, out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (a.ptr[k].type != msgpack::type::BOOLEAN)
      fail(key(i), "[" + std::to_string(k) + "]: expected a boolean, got " +
                       msgpack_type_name(a.ptr[k].type));
    out[k] = a.ptr[k].via.boolean;
  }
}

void MapReader::strings(std::size_t i, std::span<std::string_view> out) const {
  const auto& a = array(i, out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (a.ptr[k].type != msgpack::type::STR)
      fail(key(i), "[" + std::to_string(k) + "]: expected a string, got " +
                       msgpack_type_name(a.ptr[k].type));
    out[k] = std::string_view(a.ptr[k].via.str.ptr, a.ptr[k].via.str.size);
  }
}

}  // namespace stride::hal::lola
