#include "console/view/view_message.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "robot/core/error.hpp"

namespace stride::view {

namespace {

using Json = nlohmann::json;

constexpr std::size_t kMaxDepth = 16;
constexpr std::size_t kMaxLine = 4096;
constexpr std::size_t kMaxKey = 256;

[[noreturn]] void fail(const std::string& what) {
  throw Error("ws message: " + what);
}

// Control characters (a tab aside) would break the one-line errors and replies that echo text.
bool has_control(std::string_view s) {
  return std::any_of(s.begin(), s.end(), [](char c) {
    return (static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f;
  });
}

// A page's word for an error line: at most 32 bytes, control characters as '?'.
std::string printable(std::string_view word) {
  std::string out(word.substr(0, 32));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return out;
}

// Nesting deeper than kMaxDepth is refused before parsing (bounded work on any input).
void check_depth(std::string_view text) {
  std::size_t depth = 0;
  bool in_string = false, escaped = false;
  for (char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxDepth) fail("nested deeper than " + std::to_string(kMaxDepth));
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

const Json& member(const Json& m, const char* name) {
  const auto it = m.find(name);
  if (it == m.end()) fail(std::string("expected \"") + name + "\"");
  return *it;
}

std::string text_member(const Json& m, const char* name, std::size_t max) {
  const Json& v = member(m, name);
  if (!v.is_string()) fail(std::string("\"") + name + "\" should be a string");
  const std::string& s = v.get_ref<const std::string&>();
  if (s.size() > max)
    fail(std::string("\"") + name + "\" longer than " + std::to_string(max) + " characters");
  if (has_control(s)) fail(std::string("\"") + name + "\" holds a control character");
  return s;
}

std::int64_t id_member(const Json& m) {
  const Json& v = member(m, "id");
  if (!v.is_number_integer()) fail("\"id\" should be an integer");
  return v.get<std::int64_t>();
}

// Hex of a 32-byte value, lower case.
std::string hex_member(const Json& m, const char* name) {
  std::string s = text_member(m, name, 64);
  if (s.size() != 64 || s.find_first_not_of("0123456789abcdef") != std::string::npos)
    fail(std::string("\"") + name + "\" should be 64 lower-case hex digits");
  return s;
}

WatchRequest watch(const Json& m) {
  const Json& keys = member(m, "keys");
  if (!keys.is_array()) fail("\"keys\" should be an array of strings");
  if (keys.size() > kMaxWatchKeys) fail("more than " + std::to_string(kMaxWatchKeys) + " keys");
  WatchRequest w;
  for (const Json& k : keys) {
    if (!k.is_string() || k.get_ref<const std::string&>().empty() ||
        k.get_ref<const std::string&>().size() > kMaxKey ||
        has_control(k.get_ref<const std::string&>()))
      fail("\"keys\" should hold non-empty one-line strings of at most " + std::to_string(kMaxKey) +
           " characters");
    w.keys.push_back(k.get<std::string>());
  }
  return w;
}

}  // namespace

ViewRequest decode_view_message(std::string_view text) {
  check_depth(text);
  const Json m = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (m.is_discarded()) fail("not JSON (expected one object)");
  if (!m.is_object()) fail("expected a JSON object");
  const auto op_it = m.find("op");
  if (op_it == m.end() || !op_it->is_string())
    fail("expected \"op\" (cmd, watch, tree, get, times, auth)");
  const std::string& op = op_it->get_ref<const std::string&>();
  if (op == "cmd") {
    const CmdRequest c{id_member(m), text_member(m, "line", kMaxLine)};
    return c;
  }
  if (op == "watch") return watch(m);
  if (op == "tree") return TreeRequest{};
  if (op == "get") return GetRequest{id_member(m), text_member(m, "key", kMaxKey)};
  if (op == "times") {
    const auto on = m.find("on");
    if (on == m.end() || !on->is_boolean()) fail("\"on\" should be true or false");
    return TimesRequest{on->get<bool>()};
  }
  if (op == "auth") return AuthRequest{hex_member(m, "nonce"), hex_member(m, "proof")};
  fail("unknown op \"" + printable(op) + "\" (expected cmd, watch, tree, get, times, auth)");
}

}  // namespace stride::view
