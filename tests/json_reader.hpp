#pragma once
// A strict reader of the JSON Stride writes, for tests: objects, arrays, strings (with the
// escapes robot/core/json_writer.hpp produces and \uXXXX below 0x80), numbers, true, false,
// null. A test reading output through it checks that the output parses as a whole.
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace stride::test_support {

struct Json {
  using Array = std::vector<Json>;
  using Object = std::map<std::string, Json>;
  std::variant<std::nullptr_t, bool, double, std::string, std::shared_ptr<Array>,
               std::shared_ptr<Object>>
      v;

  const Json& operator[](const std::string& key) const {
    const auto& o = *std::get<std::shared_ptr<Object>>(v);
    const auto it = o.find(key);
    if (it == o.end()) throw std::runtime_error("json: no key '" + key + "'");
    return it->second;
  }
  const Json& operator[](std::size_t i) const { return std::get<std::shared_ptr<Array>>(v)->at(i); }
  std::size_t size() const {
    if (const auto* a = std::get_if<std::shared_ptr<Array>>(&v)) return (*a)->size();
    return std::get<std::shared_ptr<Object>>(v)->size();
  }
  double number() const { return std::get<double>(v); }
  const std::string& text() const { return std::get<std::string>(v); }
  bool boolean() const { return std::get<bool>(v); }
};

class JsonReader {
 public:
  // Throws std::runtime_error naming the offset of the first thing that is not JSON.
  static Json parse(const std::string& text) {
    JsonReader r(text);
    Json j = r.value();
    r.space();
    if (r.at_ != text.size()) r.fail("text after the value");
    return j;
  }

 private:
  explicit JsonReader(const std::string& t) : t_(t) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("json at " + std::to_string(at_) + ": " + what);
  }
  void space() {
    while (at_ < t_.size() &&
           (t_[at_] == ' ' || t_[at_] == '\n' || t_[at_] == '\t' || t_[at_] == '\r'))
      ++at_;
  }
  bool take(char c) {
    space();
    if (at_ < t_.size() && t_[at_] == c) return ++at_, true;
    return false;
  }
  void expect(char c) {
    if (!take(c)) fail(std::string("expected '") + c + "'");
  }
  bool word(const char* w) {
    const std::string s(w);
    if (t_.compare(at_, s.size(), s) != 0) return false;
    at_ += s.size();
    return true;
  }

  Json value() {
    space();
    if (at_ >= t_.size()) fail("expected a value");
    const char c = t_[at_];
    if (c == '{') return object();
    if (c == '[') return array();
    if (c == '"') return {string()};
    if (word("true")) return {true};
    if (word("false")) return {false};
    if (word("null")) return {nullptr};
    return {number()};
  }
  Json object() {
    expect('{');
    auto o = std::make_shared<Json::Object>();
    if (!take('}')) {
      do {
        space();
        std::string key = string();
        expect(':');
        (*o)[key] = value();
      } while (take(','));
      expect('}');
    }
    return {o};
  }
  Json array() {
    expect('[');
    auto a = std::make_shared<Json::Array>();
    if (!take(']')) {
      do a->push_back(value());
      while (take(','));
      expect(']');
    }
    return {a};
  }
  std::string string() {
    if (at_ >= t_.size() || t_[at_] != '"') fail("expected a string");
    std::string s;
    for (++at_; at_ < t_.size() && t_[at_] != '"'; ++at_) {
      if (t_[at_] != '\\') {
        s += t_[at_];
        continue;
      }
      if (++at_ >= t_.size()) break;
      const char e = t_[at_];
      if (e == 'n')
        s += '\n';
      else if (e == 't')
        s += '\t';
      else if (e == 'r')
        s += '\r';
      else if (e == 'u' && at_ + 4 < t_.size()) {
        s += static_cast<char>(std::stoi(t_.substr(at_ + 1, 4), nullptr, 16));
        at_ += 4;
      } else if (e == '"' || e == '\\' || e == '/')
        s += e;
      else
        fail("bad escape");
    }
    if (at_ >= t_.size()) fail("unterminated string");
    ++at_;
    return s;
  }
  double number() {
    const char* begin = t_.c_str() + at_;
    char* end = nullptr;
    const double d = std::strtod(begin, &end);
    if (end == begin) fail("expected a value");
    at_ += static_cast<std::size_t>(end - begin);
    return d;
  }

  const std::string& t_;
  std::size_t at_ = 0;
};

}  // namespace stride::test_support
