#include "robot/framework/type_desc.hpp"

#include <sstream>
#include <stdexcept>

namespace stride {

bool is_integer(Kind k) {
  return k == Kind::Int8 || k == Kind::UInt8 || k == Kind::Int32 || k == Kind::UInt32 ||
         k == Kind::Int64;
}
bool is_number(Kind k) {
  return is_integer(k) || k == Kind::Float || k == Kind::Double;
}

std::string type_label(const TypeDesc& d) {
  switch (d.kind) {
    case Kind::Array:
      return type_label(*d.element) + "[" + std::to_string(d.length) + "]";
    case Kind::List:
      return type_label(*d.element) + "[]";
    default:
      return d.name;
  }
}

namespace {

void describe_into(const TypeDesc& d, int indent, std::ostringstream& out) {
  const TypeDesc* leaf = &d;
  while (leaf->kind == Kind::Array || leaf->kind == Kind::List) leaf = leaf->element.get();
  if (leaf->kind == Kind::Enum) {
    out << " (";
    for (std::size_t i = 0; i < leaf->enumerators.size(); ++i)
      out << (i ? "|" : "") << leaf->enumerators[i];
    out << ")";
  }
  if (d.kind == Kind::Array && !d.element_names.empty()) {
    out << " (elements:";
    for (const auto& n : d.element_names) out << " " << n;
    out << ")";
  }
  if (leaf->kind != Kind::Struct) return;
  for (const auto& f : leaf->fields) {
    out << "\n" << std::string(indent, ' ') << f.name << ": " << type_label(*f.type);
    if (!f.unit.empty()) out << " [" << f.unit << "]";
    if (f.range) out << " in [" << f.range->min << ", " << f.range->max << "]";
    describe_into(*f.type, indent + 2, out);
  }
}

// The array flags byte; older descriptions have 0 or 1 and read the same.
constexpr std::uint8_t kVectorComponents = 1;
constexpr std::uint8_t kNamedElements = 2;  // followed by `length` names

constexpr int kMaxDepth = 32;  // a hostile description must not exhaust the stack
constexpr std::uint64_t kMaxArrayLength = 1 << 20;  // nor the memory

TypeDescPtr read_desc(ByteReader& r, int depth) {
  if (depth > kMaxDepth) throw Error("type description nested deeper than 32 levels");
  auto d = std::make_shared<TypeDesc>();
  const auto kind = r.get<std::uint8_t>();
  if (kind > static_cast<std::uint8_t>(Kind::Struct))
    throw Error("type description: unknown kind " + std::to_string(kind));
  d->kind = static_cast<Kind>(kind);
  d->name = r.get_string();
  switch (d->kind) {
    case Kind::Enum: {
      const auto n = r.get<std::uint32_t>();
      if (n > r.remaining()) throw Error("type description: enumerator count too large");
      for (std::uint32_t i = 0; i < n; ++i) d->enumerators.push_back(r.get_string());
      break;
    }
    case Kind::Array: {
      d->length = r.get<std::uint64_t>();
      if (d->length > kMaxArrayLength)
        throw Error("type description: array length " + std::to_string(d->length) + " too large");
      const auto flags = r.get<std::uint8_t>();
      if (flags > (kVectorComponents | kNamedElements))
        throw Error("type description: unknown array flags " + std::to_string(flags));
      d->vector_components = (flags & kVectorComponents) != 0;
      if (flags & kNamedElements) {
        if (d->length > r.remaining()) throw Error("type description: too many element names");
        for (std::size_t i = 0; i < d->length; ++i) d->element_names.push_back(r.get_string());
      }
      d->element = read_desc(r, depth + 1);
      break;
    }
    case Kind::List:
      d->element = read_desc(r, depth + 1);
      break;
    case Kind::Struct: {
      const auto n = r.get<std::uint32_t>();
      if (n > r.remaining()) throw Error("type description: field count too large");
      for (std::uint32_t i = 0; i < n; ++i) {
        FieldDesc f;
        f.name = r.get_string();
        f.unit = r.get_string();
        if (r.get<std::uint8_t>()) {
          const double lo = r.get<double>();
          f.range = Range{lo, r.get<double>()};
        }
        f.type = read_desc(r, depth + 1);
        d->fields.push_back(std::move(f));
      }
      break;
    }
    default:
      break;
  }
  return d;
}

}  // namespace

std::string describe_text(const TypeDesc& d) {
  std::ostringstream out;
  out << type_label(d);
  describe_into(d, 2, out);
  return out.str();
}

namespace {

void write_desc(ByteWriter& w, const TypeDesc& d, bool names) {
  w.put(static_cast<std::uint8_t>(d.kind));
  w.put_string(d.name);
  switch (d.kind) {
    case Kind::Enum:
      w.put(static_cast<std::uint32_t>(d.enumerators.size()));
      for (const auto& e : d.enumerators) w.put_string(e);
      break;
    case Kind::Array: {
      w.put(static_cast<std::uint64_t>(d.length));
      const bool named = names && !d.element_names.empty();
      w.put(static_cast<std::uint8_t>((d.vector_components ? kVectorComponents : 0) |
                                      (named ? kNamedElements : 0)));
      if (named)
        for (const auto& n : d.element_names) w.put_string(n);
      write_desc(w, *d.element, names);
      break;
    }
    case Kind::List:
      write_desc(w, *d.element, names);
      break;
    case Kind::Struct:
      w.put(static_cast<std::uint32_t>(d.fields.size()));
      for (const auto& f : d.fields) {
        w.put_string(f.name);
        w.put_string(f.unit);
        w.put(static_cast<std::uint8_t>(f.range.has_value()));
        if (f.range) {
          w.put(f.range->min);
          w.put(f.range->max);
        }
        write_desc(w, *f.type, names);
      }
      break;
    default:
      break;
  }
}

}  // namespace

void write_type_desc(ByteWriter& w, const TypeDesc& d) {
  write_desc(w, d, true);
}

TypeDescPtr read_type_desc(ByteReader& r) {
  return read_desc(r, 0);
}

bool same_type(const TypeDesc& a, const TypeDesc& b) {
  std::string x, y;
  ByteWriter wx(x), wy(y);
  write_desc(wx, a, false);
  write_desc(wy, b, false);
  return x == y;
}

TypeDescPtr with_element_names(const TypeDescPtr& array, std::span<const std::string_view> names) {
  if (array->kind != Kind::Array || array->length != names.size())
    throw std::logic_error("element names need an array of " + std::to_string(names.size()) +
                           " elements, not " + type_label(*array));
  auto named = std::make_shared<TypeDesc>(*array);
  named->element_names.assign(names.begin(), names.end());
  return named;
}

int element_index(const TypeDesc& array, std::string_view name) {
  for (std::size_t i = 0; i < array.element_names.size(); ++i)
    if (array.element_names[i] == name) return static_cast<int>(i);
  return -1;
}

}  // namespace stride
