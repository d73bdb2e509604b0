#pragma once
// A decoded value described by a TypeDesc: the generic text, partial-update and CSV forms work on
// this tree, so they need no per-type code and also work for types from another revision.
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "robot/framework/type_desc.hpp"

namespace stride {

struct Value {
  using List = std::vector<Value>;  // struct fields, array or list elements
  std::variant<bool, std::int64_t, double, std::string, List> data;  // enums: index as int64
};

Value default_value(const TypeDesc& d);
Value read_value(const TypeDesc& d, ByteReader& r);
void write_value(const TypeDesc& d, const Value& v, ByteWriter& w);

// Whole value as text: structs {a=1, b=[1, 2]}, enums by name, strings quoted, doubles in the
// shortest form that reads back to the same bits.
std::string print_value(const TypeDesc& d, const Value& v);

// Applies `text` to `v`: either a whole value ("{...}") or updates "path=value path=value ..."
// with paths like position[3], cop.x, gains.kp. All or nothing: on error `v` is unchanged and the
// one-line message names `root_name.path` and what was expected. Numbers::Finite refuses nan and
// inf (and a float beyond its range) as representations need; parameters may hold NaN.
enum class Numbers { Any, Finite };
void update_value(const TypeDesc& d, Value& v, std::string_view text, std::string_view root_name,
                  Numbers numbers = Numbers::Any);

// The sub-description and sub-value at `path` ("" = the whole value); throws naming the path.
std::pair<const TypeDesc*, const Value*> value_at(const TypeDesc& d, const Value& v,
                                                  std::string_view path,
                                                  std::string_view root_name);

// Flattened leaf paths ("position[3]", "cop[0]") and their texts; lists become one text cell.
void csv_columns(const TypeDesc& d, const std::string& prefix, std::vector<std::string>& out);
void csv_cells(const TypeDesc& d, const Value& v, std::vector<std::string>& out);

}  // namespace stride
