#include "robot/runtime/finite_parameters.hpp"

#include <cmath>
#include <string>

#include "robot/core/error.hpp"

namespace stride {

namespace {

std::string child_path(const TypeDesc& d, const std::string& path, std::size_t i) {
  if (d.kind == Kind::Struct) return path + (path.empty() ? "" : ".") + d.fields[i].name;
  return path + "[" + std::to_string(i) + "]";
}

const TypeDesc& child_type(const TypeDesc& d, std::size_t i) {
  return d.kind == Kind::Struct ? *d.fields[i].type : *d.element;
}

void check(const TypeDesc& d, const Value& after, const Value* defaults, const std::string& path,
           std::string_view root) {
  if (const auto* x = std::get_if<double>(&after.data)) {
    const auto* fallback = defaults ? std::get_if<double>(&defaults->data) : nullptr;
    const bool may_be_nan = fallback && std::isnan(*fallback) && std::isnan(*x);
    if (!std::isfinite(*x) && !may_be_nan)
      throw Error(std::string(root) + "." + path + ": " + (std::isnan(*x) ? "nan" : "inf") +
                  " refused: a parameter never becomes NaN or infinite (give a number)");
    return;
  }
  const auto* a = std::get_if<Value::List>(&after.data);
  if (!a) return;
  // A list's elements have no defaults of their own: none of them may be NaN.
  const auto* f =
      defaults && d.kind != Kind::List ? std::get_if<Value::List>(&defaults->data) : nullptr;
  for (std::size_t i = 0; i < a->size(); ++i)
    check(child_type(d, i), (*a)[i], f && i < f->size() ? &(*f)[i] : nullptr,
          child_path(d, path, i), root);
}

}  // namespace

void refuse_nonfinite(const TypeDesc& d, const Value& after, const Value& defaults,
                      std::string_view root) {
  check(d, after, &defaults, "", root);
}

}  // namespace stride
