#include "robot/framework/leaf_reader.hpp"

#include <bit>
#include <cstring>

#include "robot/core/error.hpp"

namespace stride {
namespace {

bool fixed_size(const TypeDesc& d) {
  switch (d.kind) {
    case Kind::String:
    case Kind::List:
      return false;
    case Kind::Array:
      return fixed_size(*d.element);
    case Kind::Struct:
      for (const auto& f : d.fields)
        if (!fixed_size(*f.type)) return false;
      return true;
    default:
      return true;
  }
}

// The leaf's value as a double, from its encoded bytes at `p`.
double leaf_number(Kind kind, const char* p) {
  const auto get = [p](auto v) {
    std::memcpy(&v, p, sizeof v);
    return static_cast<double>(v);
  };
  switch (kind) {
    case Kind::Bool:
    case Kind::UInt8:
      return get(std::uint8_t{});
    case Kind::Int8:
      return get(std::int8_t{});
    case Kind::Int32:
    case Kind::Enum:
      return get(std::int32_t{});
    case Kind::UInt32:
      return get(std::uint32_t{});
    case Kind::Int64:
      return get(std::int64_t{});
    case Kind::Float:
      return get(float{});
    default:
      return get(double{});
  }
}

double value_number(const Value& v) {
  if (const auto* b = std::get_if<bool>(&v.data)) return *b ? 1 : 0;
  if (const auto* i = std::get_if<std::int64_t>(&v.data)) return static_cast<double>(*i);
  return std::get<double>(v.data);
}

// Sets the leaf to a value whose every encoded byte differs from the other pattern's (0x01 in
// every byte against 0x7e in every byte).
void set_pattern(Value& leaf, Kind kind, bool second) {
  if (kind == Kind::Bool)
    leaf.data = second;
  else if (kind == Kind::Double)
    leaf.data = std::bit_cast<double>(second ? 0x7e7e7e7e7e7e7e7eULL : 0x0101010101010101ULL);
  else if (kind == Kind::Float)
    leaf.data = static_cast<double>(std::bit_cast<float>(second ? 0x7e7e7e7eU : 0x01010101U));
  else
    leaf.data = std::int64_t{second ? 0x7e : 0x01};  // the first byte differs, which is enough
}

}  // namespace

LeafReader::LeafReader(const TypeDesc& type, std::string_view path, std::string_view root)
    : path_(path), root_(root) {
  Value probe = default_value(type);
  const auto [desc, leaf] = value_at(type, probe, path, root);
  if (!is_number(desc->kind) && desc->kind != Kind::Bool && desc->kind != Kind::Enum)
    throw Error(root_ + (path_.empty() ? "" : "." + path_) + ": is a " + type_label(*desc) +
                ", not a number");
  kind_ = desc->kind;
  if (!fixed_size(type)) return;
  // Encode the value with two leaf patterns: the first differing byte is the leaf's offset.
  std::string a, b;
  Value& target = const_cast<Value&>(*leaf);
  set_pattern(target, kind_, false);
  ByteWriter wa(a);
  write_value(type, probe, wa);
  set_pattern(target, kind_, true);
  ByteWriter wb(b);
  write_value(type, probe, wb);
  std::size_t k = 0;
  while (k < a.size() && a[k] == b[k]) ++k;
  offset_ = static_cast<std::ptrdiff_t>(k);
}

double LeafReader::read(const Slot& slot, std::string& scratch) const {
  scratch.clear();
  ByteWriter w(scratch);
  slot.encode(w);
  return read_encoded(slot, scratch);
}

double LeafReader::read_encoded(const Slot& slot, const std::string& bytes) const {
  if (offset_ >= 0) return leaf_number(kind_, bytes.data() + offset_);
  ByteReader r(bytes);
  const Value v = read_value(slot.desc(), r);
  return value_number(*value_at(slot.desc(), v, path_, root_).second);
}

}  // namespace stride
