#include "console/view/type_desc_json.hpp"

namespace stride::view {

namespace {
constexpr int kMaxDepth = 32;  // descriptions from a remote robot are data: bounded recursion

Json describe(const TypeDesc& d, const std::string& unit, int depth) {
  if (depth > kMaxDepth) return {{"kind", "string"}};
  switch (d.kind) {
    case Kind::Bool:
      return {{"kind", "bool"}};
    case Kind::String:
      return {{"kind", "string"}};
    case Kind::Enum:
      return {{"kind", "enum"}, {"names", d.enumerators}};
    case Kind::Array:
    case Kind::List: {
      Json a = {{"kind", "array"},
                {"size", d.kind == Kind::Array ? Json(d.length) : Json(nullptr)},
                {"item", d.element ? describe(*d.element, unit, depth + 1) : Json(nullptr)}};
      if (!d.element_names.empty()) a["names"] = d.element_names;
      return a;
    }
    case Kind::Struct: {
      Json fields = Json::array();
      for (const FieldDesc& f : d.fields)
        fields.push_back({{"name", f.name},
                          {"type", f.type ? describe(*f.type, f.unit, depth + 1) : Json(nullptr)}});
      return {{"kind", "struct"}, {"name", d.name}, {"fields", std::move(fields)}};
    }
    default:
      return {{"kind", "number"}, {"unit", unit}};
  }
}

}  // namespace

Json type_desc_json(const TypeDesc& d, const std::string& unit) {
  return describe(d, unit, 0);
}

}  // namespace stride::view
