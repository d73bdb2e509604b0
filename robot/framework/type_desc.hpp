#pragma once
// Runtime description of a reflected type: enough to print, parse, flatten and decode its binary
// form without the C++ type, e.g. in a console built from another revision.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "robot/framework/byte_io.hpp"
#include "robot/framework/reflect.hpp"

namespace stride {

enum class Kind : std::uint8_t {
  Bool,
  Int8,
  UInt8,
  Int32,
  UInt32,
  Int64,
  Float,
  Double,
  String,
  Enum,
  Array,
  List,
  Struct
};

struct TypeDesc;
using TypeDescPtr = std::shared_ptr<const TypeDesc>;

struct FieldDesc {
  std::string name;
  std::string unit;
  std::optional<Range> range;
  TypeDescPtr type;
};

struct TypeDesc {
  Kind kind = Kind::Double;
  std::string name;                        // "double", an enum's or struct's name, "array", "list"
  std::vector<std::string> enumerators;    // Enum: names of 0..N-1
  std::size_t length = 0;                  // Array: element count
  std::vector<std::string> element_names;  // Array: names of elements 0..length-1, or none
  TypeDescPtr element;                     // Array, List
  std::vector<FieldDesc> fields;           // Struct
  bool vector_components = false;          // Eigen vector: paths may say .x .y .z .w
};

bool is_integer(Kind k);
bool is_number(Kind k);  // integer or floating point

// e.g. "double[25]", "ServoMode", "JointRequest"
std::string type_label(const TypeDesc& d);
// Multi-line listing of fields with types and units, for `help`-like console output.
std::string describe_text(const TypeDesc& d);

void write_type_desc(ByteWriter& w, const TypeDesc& d);
TypeDescPtr read_type_desc(ByteReader& r);
// Same layout and names; element names are labels, so they do not make another type.
bool same_type(const TypeDesc& a, const TypeDesc& b);
// A copy of an array description with its elements named (Field::named); throws std::logic_error
// if it is no array of names.size() elements (a mistake in a field list).
TypeDescPtr with_element_names(const TypeDescPtr& array, std::span<const std::string_view> names);
// Index of `name` among an array's element names, or -1.
int element_index(const TypeDesc& array, std::string_view name);

}  // namespace stride
