#include "robot/framework/value.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride {

namespace {

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};

std::pair<std::int64_t, std::int64_t> integer_bounds(Kind k) {
  switch (k) {
    case Kind::Int8:
      return {-128, 127};
    case Kind::UInt8:
      return {0, 255};
    case Kind::Int32:
      return {std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max()};
    case Kind::UInt32:
      return {0, std::numeric_limits<std::uint32_t>::max()};
    default:
      return {std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max()};
  }
}

std::string number_text(double x, bool single) {
  char buf[64];
  auto res = single ? std::to_chars(buf, buf + sizeof buf, static_cast<float>(x))
                    : std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, res.ptr);
}

std::string quoted_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

void print_into(const TypeDesc& d, const Value& v, std::string& out) {
  switch (d.kind) {
    case Kind::Bool:
      out += std::get<bool>(v.data) ? "true" : "false";
      return;
    case Kind::Float:
      out += number_text(std::get<double>(v.data), true);
      return;
    case Kind::Double:
      out += number_text(std::get<double>(v.data), false);
      return;
    case Kind::String:
      out += quoted_string(std::get<std::string>(v.data));
      return;
    case Kind::Enum: {
      const auto i = std::get<std::int64_t>(v.data);
      out += i >= 0 && i < static_cast<std::int64_t>(d.enumerators.size()) ? d.enumerators[i]
                                                                           : std::to_string(i);
      return;
    }
    case Kind::Array:
    case Kind::List: {
      const auto& items = std::get<Value::List>(v.data);
      const bool named = d.element_names.size() == items.size();
      out += '[';
      for (std::size_t i = 0; i < items.size(); ++i) {
        if (i) out += ", ";
        if (named) out += d.element_names[i] + "=";
        print_into(*d.element, items[i], out);
      }
      out += ']';
      return;
    }
    case Kind::Struct: {
      const auto& items = std::get<Value::List>(v.data);
      out += '{';
      for (std::size_t i = 0; i < items.size(); ++i) {
        out += (i ? ", " : "") + d.fields[i].name + "=";
        print_into(*d.fields[i].type, items[i], out);
      }
      out += '}';
      return;
    }
    default:
      out += std::to_string(std::get<std::int64_t>(v.data));
      return;
  }
}

// Where a path points: the sub-description, the sub-value, and the range of the enclosing field.
struct Target {
  const TypeDesc* desc;
  Value* value;
  std::optional<Range> range;
};

std::string field_list(const TypeDesc& d) {
  std::string s;
  for (const auto& f : d.fields) s += (s.empty() ? "" : ", ") + f.name;
  return s;
}

bool is_ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Follows "a.b[3].x" from (d, v); errors name `root.path-so-far`.
Target navigate(const TypeDesc& d, Value& v, std::string_view path, std::string_view root) {
  Target t{&d, &v, std::nullopt};
  std::string where(root);
  std::size_t i = 0;
  auto fail = [&](const std::string& what) -> InputError {
    return InputError(where + ": " + what);
  };
  while (i < path.size()) {
    if (path[i] == '[') {
      const auto close = path.find(']', i);
      if (close == std::string_view::npos) throw fail("expected ']' in path " + quote(path));
      const auto digits = path.substr(i + 1, close - i - 1);
      if (t.desc->kind != Kind::Array && t.desc->kind != Kind::List)
        throw fail("is a " + type_label(*t.desc) + ", not an array");
      std::size_t index = 0;
      auto res = std::from_chars(digits.data(), digits.data() + digits.size(), index);
      if (res.ec != std::errc() || res.ptr != digits.data() + digits.size()) {
        const int named = element_index(*t.desc, digits);
        if (named < 0 && !t.desc->element_names.empty())
          throw fail("no element " + quote(digits) + " (get <key> ? lists the names)");
        if (named < 0) throw fail("expected an index in [], got " + quote(digits));
        index = static_cast<std::size_t>(named);
      }
      auto& items = std::get<Value::List>(t.value->data);
      where.append("[").append(digits).append("]");
      if (index >= items.size())
        throw fail("index out of range [0, " + std::to_string(items.size()) + ")");
      t = {t.desc->element.get(), &items[index], t.range};
      i = close + 1;
      continue;
    }
    if (path[i] == '.')
      ++i;
    else if (i != 0)
      throw fail("expected '.' or '[' in path " + quote(path));
    std::size_t end = i;
    while (end < path.size() && is_ident_char(path[end])) ++end;
    const auto name = path.substr(i, end - i);
    if (name.empty()) throw fail("expected a field name in path " + quote(path));
    if (t.desc->kind == Kind::Array && t.desc->vector_components && name.size() == 1 &&
        std::string_view("xyzw").find(name[0]) != std::string_view::npos) {
      const auto index = std::string_view("xyzw").find(name[0]);
      auto& items = std::get<Value::List>(t.value->data);
      where.append(".").append(name);
      if (index >= items.size())
        throw fail("vector has only " + std::to_string(items.size()) + " components");
      t = {t.desc->element.get(), &items[index], t.range};
    } else if (t.desc->kind == Kind::Struct) {
      std::size_t k = 0;
      while (k < t.desc->fields.size() && t.desc->fields[k].name != name) ++k;
      if (k == t.desc->fields.size())
        throw fail("no field " + quote(name) + " (fields: " + field_list(*t.desc) + ")");
      where.append(".").append(name);
      const auto& f = t.desc->fields[k];
      t = {f.type.get(), &std::get<Value::List>(t.value->data)[k], f.range};
    } else {
      throw fail("is a " + type_label(*t.desc) + ", has no field " + quote(name));
    }
    i = end;
  }
  return t;
}

class Parser {
 public:
  Parser(std::string_view text, std::string_view root, Numbers numbers)
      : s_(text), root_(root), numbers_(numbers) {}

  void skip_space() {
    while (pos_ < s_.size() &&
           (std::isspace(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == ','))
      ++pos_;
  }
  bool at_end() {
    skip_space();
    return pos_ >= s_.size();
  }
  bool peek(char c) {
    skip_space();
    return pos_ < s_.size() && s_[pos_] == c;
  }
  bool accept(char c) {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    if (pos_ < s_.size() && s_[pos_] == c) return ++pos_, true;
    return false;
  }
  std::string_view word() {
    skip_space();
    const auto start = pos_;
    while (pos_ < s_.size() &&
           std::string_view(" \t\r\n,{}[]=\"").find(s_[pos_]) == std::string_view::npos)
      ++pos_;
    return s_.substr(start, pos_ - start);
  }
  std::string_view path() {
    skip_space();
    const auto start = pos_;
    while (pos_ < s_.size() && s_[pos_] != '=' &&
           !std::isspace(static_cast<unsigned char>(s_[pos_])))
      ++pos_;
    return s_.substr(start, pos_ - start);
  }
  std::string next_token() {
    skip_space();
    if (pos_ >= s_.size()) return "end of text";
    const auto w = s_.substr(pos_, std::min<std::size_t>(20, s_.size() - pos_));
    return "'" + std::string(w.substr(0, w.find_first_of(" \t\n"))) + "'";
  }
  [[noreturn]] void fail(const std::string& where, const std::string& expected) {
    throw InputError(where + ": expected " + expected + ", got " + next_token());
  }
  [[noreturn]] void fail_at(const std::string& where, std::string_view token,
                            const std::string& expected) {
    throw InputError(where + ": expected " + expected + ", got " + quote(token));
  }

  void parse(const TypeDesc& d, Value& v, const std::string& where,
             const std::optional<Range>& range);

 private:
  std::string quoted_or_word(const std::string& where);
  void parse_sequence(const TypeDesc& d, Value& v, const std::string& where,
                      const std::optional<Range>& range);
  // "[LAnklePitch=0.1, RAnklePitch=0.1]" after the '[': sets the named elements, keeps the rest.
  // Returns false, reading nothing, if the first element has no name.
  bool parse_named_elements(const TypeDesc& d, Value::List& items, const std::string& where,
                            const std::optional<Range>& range) {
    if (d.element_names.empty()) return false;
    const std::size_t start = pos_;
    word();
    const bool named = accept('=');
    pos_ = start;
    if (!named) return false;
    while (!accept(']')) {
      if (at_end()) fail(where, "']'");
      const auto name = word();
      const int i = element_index(d, name);
      if (i < 0) fail_at(where, name, "an element name (get <key> ? lists them)");
      if (!accept('=')) fail(where + "[" + std::string(name) + "]", "'='");
      parse(*d.element, items[i], where + "[" + std::string(name) + "]", range);
    }
    return true;
  }

  void check_range(const std::string& where, double x, std::string_view token,
                   const std::optional<Range>& range) {
    if (range && !(x >= range->min && x <= range->max))
      throw InputError(where + ": " + std::string(token) + " is outside [" +
                       number_text(range->min, false) + ", " + number_text(range->max, false) +
                       "]");
  }
  std::string_view s_;
  std::string root_;
  Numbers numbers_;
  std::size_t pos_ = 0;
};

// A string value: "quoted" (with \\ escapes, \\n a newline) or one word.
std::string Parser::quoted_or_word(const std::string& where) {
  skip_space();
  if (pos_ >= s_.size() || s_[pos_] != '"') return std::string(word());
  std::string out;
  for (++pos_; pos_ < s_.size() && s_[pos_] != '"'; ++pos_) {
    if (s_[pos_] == '\\' && pos_ + 1 < s_.size()) {
      ++pos_;
      out += s_[pos_] == 'n' ? '\n' : s_[pos_];
    } else {
      out += s_[pos_];
    }
  }
  if (pos_ >= s_.size()) fail(where, "a closing '\"'");
  ++pos_;
  return out;
}

// `[a b c]` for an array or list, or named elements (`[LAnklePitch=0.1 ...]`).
void Parser::parse_sequence(const TypeDesc& d, Value& v, const std::string& where,
                            const std::optional<Range>& range) {
  if (!accept('[')) fail(where, "'['");
  auto& items = std::get<Value::List>(v.data);
  if (parse_named_elements(d, items, where, range)) return;
  std::size_t n = 0;
  for (;; ++n) {
    skip_space();
    if (accept(']')) break;
    if (d.kind == Kind::Array && n >= d.length)
      fail(where, "']' after " + std::to_string(d.length) + " elements");
    if (d.kind == Kind::List && n >= items.size()) items.push_back(default_value(*d.element));
    parse(*d.element, items[n], where + "[" + std::to_string(n) + "]", range);
  }
  if (d.kind == Kind::Array && n != d.length)
    throw InputError(where + ": expected " + std::to_string(d.length) + " elements, got " +
                     std::to_string(n));
  items.resize(n);
}

void Parser::parse(const TypeDesc& d, Value& v, const std::string& where,
                   const std::optional<Range>& range) {
  switch (d.kind) {
    case Kind::Bool: {
      const auto w = word();
      if (w == "true" || w == "on" || w == "1")
        v.data = true;
      else if (w == "false" || w == "off" || w == "0")
        v.data = false;
      else
        fail_at(where, w, "true or false");
      return;
    }
    case Kind::Float:
    case Kind::Double: {
      const auto w = word();
      double x = 0;
      auto res = std::from_chars(w.data(), w.data() + w.size(), x);
      if (w.empty() || res.ec != std::errc() || res.ptr != w.data() + w.size())
        fail_at(where, w, "a number");
      if (d.kind == Kind::Float) x = static_cast<float>(x);
      // NaN or infinity in a representation only spreads through the controllers (parameters
      // may use NaN to mean "from the preset").
      if (numbers_ == Numbers::Finite && !std::isfinite(x)) fail_at(where, w, "a finite number");
      check_range(where, x, w, range);
      v.data = x;
      return;
    }
    case Kind::String:
      v.data = quoted_or_word(where);
      return;
    case Kind::Enum: {
      const auto w = word();
      for (std::size_t i = 0; i < d.enumerators.size(); ++i)
        if (d.enumerators[i] == w) return void(v.data = static_cast<std::int64_t>(i));
      std::string names;
      for (const auto& e : d.enumerators) names += (names.empty() ? "" : "|") + e;
      fail_at(where, w, "one of " + names);
    }
    case Kind::Array:
    case Kind::List:
      return parse_sequence(d, v, where, range);
    case Kind::Struct: {
      if (!accept('{')) fail(where, "'{'");
      while (!accept('}')) {
        if (at_end()) fail(where, "'}'");
        const auto p = path();
        auto t = navigate(d, v, p, where);
        if (!accept('=')) fail(where + "." + std::string(p), "'='");
        parse(*t.desc, *t.value, where + "." + std::string(p), t.range);
      }
      return;
    }
    default: {
      const auto w = word();
      std::int64_t x = 0;
      auto res = std::from_chars(w.data(), w.data() + w.size(), x);
      const auto [lo, hi] = integer_bounds(d.kind);
      if (w.empty() || res.ec != std::errc() || res.ptr != w.data() + w.size() || x < lo || x > hi)
        fail_at(where, w, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
      check_range(where, static_cast<double>(x), w, range);
      v.data = x;
      return;
    }
  }
}

}  // namespace

Value default_value(const TypeDesc& d) {
  switch (d.kind) {
    case Kind::Bool:
      return {false};
    case Kind::Float:
    case Kind::Double:
      return {0.0};
    case Kind::String:
      return {std::string()};
    case Kind::Array:
      return {Value::List(d.length, default_value(*d.element))};
    case Kind::List:
      return {Value::List()};
    case Kind::Struct: {
      Value::List items;
      for (const auto& f : d.fields) items.push_back(default_value(*f.type));
      return {std::move(items)};
    }
    default:
      return {std::int64_t{0}};
  }
}

namespace {

// Elements of an empty struct take no bytes, so the bytes left cannot bound how many values a
// hostile description makes; every array or list element spends one unit of this budget.
Value read_bounded(const TypeDesc& d, ByteReader& r, std::size_t& budget) {
  switch (d.kind) {
    case Kind::Bool:
      return {r.get<std::uint8_t>() != 0};
    case Kind::Int8:
      return {std::int64_t{r.get<std::int8_t>()}};
    case Kind::UInt8:
      return {std::int64_t{r.get<std::uint8_t>()}};
    case Kind::Int32:
    case Kind::Enum:
      return {std::int64_t{r.get<std::int32_t>()}};
    case Kind::UInt32:
      return {std::int64_t{r.get<std::uint32_t>()}};
    case Kind::Int64:
      return {r.get<std::int64_t>()};
    case Kind::Float:
      return {double{r.get<float>()}};
    case Kind::Double:
      return {r.get<double>()};
    case Kind::String:
      return {r.get_string()};
    case Kind::Array:
    case Kind::List: {
      const std::size_t n = d.kind == Kind::Array ? d.length : r.get<std::uint32_t>();
      if (n > budget)
        throw Error("binary data: " + std::to_string(n) + " elements but only " +
                    std::to_string(r.remaining()) + " bytes left");
      budget -= n;
      Value::List items;
      items.reserve(n);
      for (std::size_t i = 0; i < n; ++i) items.push_back(read_bounded(*d.element, r, budget));
      return {std::move(items)};
    }
    case Kind::Struct: {
      Value::List items;
      for (const auto& f : d.fields) items.push_back(read_bounded(*f.type, r, budget));
      return {std::move(items)};
    }
  }
  throw Error("unknown kind in type description");
}

}  // namespace

Value read_value(const TypeDesc& d, ByteReader& r) {
  std::size_t budget = 4 * r.remaining() + 4096;
  return read_bounded(d, r, budget);
}

void write_value(const TypeDesc& d, const Value& v, ByteWriter& w) {
  switch (d.kind) {
    case Kind::Bool:
      w.put(static_cast<std::uint8_t>(std::get<bool>(v.data)));
      return;
    case Kind::Int8:
      w.put(static_cast<std::int8_t>(std::get<std::int64_t>(v.data)));
      return;
    case Kind::UInt8:
      w.put(static_cast<std::uint8_t>(std::get<std::int64_t>(v.data)));
      return;
    case Kind::Int32:
    case Kind::Enum:
      w.put(static_cast<std::int32_t>(std::get<std::int64_t>(v.data)));
      return;
    case Kind::UInt32:
      w.put(static_cast<std::uint32_t>(std::get<std::int64_t>(v.data)));
      return;
    case Kind::Int64:
      w.put(std::get<std::int64_t>(v.data));
      return;
    case Kind::Float:
      w.put(static_cast<float>(std::get<double>(v.data)));
      return;
    case Kind::Double:
      w.put(std::get<double>(v.data));
      return;
    case Kind::String:
      w.put_string(std::get<std::string>(v.data));
      return;
    case Kind::Array:
    case Kind::List: {
      const auto& items = std::get<Value::List>(v.data);
      if (d.kind == Kind::List) w.put(static_cast<std::uint32_t>(items.size()));
      for (const auto& e : items) write_value(*d.element, e, w);
      return;
    }
    case Kind::Struct: {
      const auto& items = std::get<Value::List>(v.data);
      for (std::size_t i = 0; i < d.fields.size(); ++i) write_value(*d.fields[i].type, items[i], w);
      return;
    }
  }
}

std::string print_value(const TypeDesc& d, const Value& v) {
  std::string out;
  print_into(d, v, out);
  return out;
}

void update_value(const TypeDesc& d, Value& v, std::string_view text, std::string_view root_name,
                  Numbers numbers) {
  Value copy = v;
  Parser p(text, root_name, numbers);
  const std::string root(root_name);
  if (p.at_end()) throw InputError(root + ": expected field=value or a whole value, got nothing");
  if (d.kind != Kind::Struct || p.peek('{')) {
    p.parse(d, copy, root, std::nullopt);
    if (!p.at_end()) p.fail(root, "end of text after the value");
  } else {
    while (!p.at_end()) {
      const auto path = p.path();
      auto t = navigate(d, copy, path, root);
      const auto where = root + "." + std::string(path);
      if (!p.accept('=')) p.fail(where, "'='");
      p.parse(*t.desc, *t.value, where, t.range);
    }
  }
  v = std::move(copy);
}

std::pair<const TypeDesc*, const Value*> value_at(const TypeDesc& d, const Value& v,
                                                  std::string_view path,
                                                  std::string_view root_name) {
  auto t = navigate(d, const_cast<Value&>(v), path, root_name);
  return {t.desc, t.value};
}

void csv_columns(const TypeDesc& d, const std::string& prefix, std::vector<std::string>& out) {
  if (d.kind == Kind::Struct) {
    for (const auto& f : d.fields)
      csv_columns(*f.type, prefix.empty() ? f.name : prefix + "." + f.name, out);
  } else if (d.kind == Kind::Array) {
    const bool named = d.element_names.size() == d.length;
    for (std::size_t i = 0; i < d.length; ++i)
      csv_columns(*d.element, prefix + "[" + (named ? d.element_names[i] : std::to_string(i)) + "]",
                  out);
  } else {
    out.push_back(prefix);
  }
}

void csv_cells(const TypeDesc& d, const Value& v, std::vector<std::string>& out) {
  if (d.kind == Kind::Struct) {
    const auto& items = std::get<Value::List>(v.data);
    for (std::size_t i = 0; i < d.fields.size(); ++i) csv_cells(*d.fields[i].type, items[i], out);
  } else if (d.kind == Kind::Array) {
    for (const auto& e : std::get<Value::List>(v.data)) csv_cells(*d.element, e, out);
  } else if (d.kind == Kind::String) {
    out.push_back(std::get<std::string>(v.data));
  } else {
    out.push_back(print_value(d, v));
  }
}

}  // namespace stride
