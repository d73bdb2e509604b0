// The house's size rules, measured: no source file over 600 lines anywhere, and no function over
// 80 lines outside tests/ (docs/studies.md, issue 52). Functions are found by a brace counter over
// the code with comments and string literals blanked: a `{` opening outside any function, whose
// head (the text since the previous `;`, `{` or `}`) has a parameter list and is no namespace,
// class or initialiser, starts a function that its matching `}` ends; lambdas and blocks inside
// count towards it. Its length runs from the head's first line to the closing brace.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tests/docs/doc_files.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::read_text;
using test_support::source_dir;

constexpr int kMaxFunctionLines = 80;
constexpr int kMaxFileLines = 600;

// Comments and literals (plain, character and raw strings) replaced by blanks, newlines kept.
std::string code_only(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  std::size_t i = 0;
  auto blank_to = [&](std::size_t end) {
    for (; i < end && i < s.size(); ++i) out += s[i] == '\n' ? '\n' : ' ';
  };
  while (i < s.size()) {
    if (s.compare(i, 2, "//") == 0) {
      blank_to(s.find('\n', i) == std::string::npos ? s.size() : s.find('\n', i));
    } else if (s.compare(i, 2, "/*") == 0) {
      blank_to(s.find("*/", i + 2) == std::string::npos ? s.size() : s.find("*/", i + 2) + 2);
    } else if (s.compare(i, 2, "R\"") == 0 &&
               (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1])))) {
      const std::size_t open = s.find('(', i);
      const std::string close = ")" + s.substr(i + 2, open - i - 2) + "\"";
      const std::size_t end = s.find(close, open);
      blank_to(end == std::string::npos ? s.size() : end + close.size());
    } else if (s[i] == '"' ||
               (s[i] == '\'' && (i == 0 || !std::isalnum(static_cast<unsigned char>(s[i - 1]))))) {
      const char quote = s[i];
      std::size_t j = i + 1;
      while (j < s.size() && s[j] != quote) j += s[j] == '\\' ? 2 : 1;
      blank_to(j + 1);
    } else {
      out += s[i++];
    }
  }
  return out;
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\n\r");
  return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(" \t\n\r") - a + 1);
}

enum class Block { Scope, Function, Initialiser, Other };

// What a `{` opens, from its head.
Block block_of(const std::string& head) {
  static const std::regex scope(
      R"(^(template\s*<[^{]*>\s*)?(namespace|struct|class|union|enum)\b)");
  static const std::regex ctor_init(R"(\)\s*:)");
  static const std::regex ends_like_signature(
      R"((\)|const|noexcept|override|final|mutable|->\s*[\w:<>,\s*&]+)$)");
  const std::string h = trimmed(head);
  if (std::regex_search(h, scope) || h.rfind("extern", 0) == 0) return Block::Scope;
  if (h.find(')') == std::string::npos || h.back() == '=') return Block::Other;
  // `Foo() : a_{1}, b_(2) {`: the braces after a member name in the list initialise it.
  if (std::regex_search(h, ctor_init) && !std::regex_search(h, ends_like_signature) &&
      (std::isalnum(static_cast<unsigned char>(h.back())) || h.back() == '_' || h.back() == '>'))
    return Block::Initialiser;
  return Block::Function;
}

struct Function {
  int first = 0, last = 0;
  int lines() const { return last - first + 1; }
};

std::vector<Function> functions_in(const std::string& text) {
  const std::string s = code_only(text);
  std::vector<Function> out;
  struct Open {
    Block block;
    int line;
  };
  std::vector<Open> stack;
  std::size_t head_start = 0;
  int line = 1;
  auto in_function = [&] {
    for (const Open& o : stack)
      if (o.block == Block::Function) return true;
    return false;
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '\n') ++line;
    if (c != ';' && c != '{' && c != '}') continue;
    if (c == '{') {
      const std::string head = s.substr(head_start, i - head_start);
      const Block b = in_function() ? Block::Other : block_of(head);
      const std::string from_first_word =
          head.substr(std::min(head.size(), head.find_first_not_of(" \t\n\r")));
      const int head_line =
          line - static_cast<int>(std::count(from_first_word.begin(), from_first_word.end(), '\n'));
      stack.push_back({b, head_line});
      if (b == Block::Initialiser) continue;  // the function's head goes on after it
    } else if (c == '}' && !stack.empty()) {
      const Open o = stack.back();
      stack.pop_back();
      if (o.block == Block::Function && !in_function()) out.push_back({o.line, line});
      if (o.block == Block::Initialiser) continue;
    }
    head_start = i + 1;
  }
  return out;
}

std::vector<fs::path> sources(bool with_tests) {
  std::vector<fs::path> out;
  for (const char* folder : {"robot", "behaviours", "simulator", "console", "bench", "tests"}) {
    if (!with_tests && std::string(folder) == "tests") continue;
    for (const auto& e : fs::recursive_directory_iterator(source_dir() / folder)) {
      const auto ext = e.path().extension();
      if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp" || ext == ".h"))
        out.push_back(e.path());
    }
  }
  return out;
}

std::string repo_path(const fs::path& p) {
  return fs::relative(p, source_dir()).generic_string();
}

TEST(CodeSize, NoSourceFileIsOver600Lines) {
  for (const fs::path& p : sources(true)) {
    const std::string text = read_text(p);
    const auto lines = std::count(text.begin(), text.end(), '\n');
    EXPECT_LE(lines, kMaxFileLines) << repo_path(p) << " has " << lines << " lines";
  }
}

TEST(CodeSize, NoFunctionOutsideTestsIsOver80Lines) {
  for (const fs::path& p : sources(false))
    for (const Function& f : functions_in(read_text(p)))
      EXPECT_LE(f.lines(), kMaxFunctionLines) << repo_path(p) << ":" << f.first << ": a function of "
                                              << f.lines() << " lines; split it into named steps";
}

// The counter itself, on code whose functions are known.
TEST(CodeSize, TheCounterFindsFunctionsAndSkipsScopesInitialisersAndLiterals) {
  const std::string code =
      "namespace a {\n"                        // 1
      "struct S {\n"                           // 2
      "  S() : x_{1}, y_(2) {\n"               // 3
      "    f(\"}\");  // }\n"                  // 4
      "  }\n"                                  // 5
      "  int x_, y_;\n"                        // 6
      "};\n"                                   // 7
      "const int v[] = {1, 2};\n"              // 8
      "int g(int k)\n"                         // 9
      "    noexcept {\n"                       // 10
      "  auto l = [&] { return '{'; };\n"      // 11
      "  /* { */ return R\"x({)x\"[0] + k;\n"  // 12
      "}\n"                                    // 13
      "}  // namespace a\n";                   // 14
  const std::vector<Function> f = functions_in(code);
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].first, 3);
  EXPECT_EQ(f[0].last, 5);
  EXPECT_EQ(f[1].first, 9);
  EXPECT_EQ(f[1].last, 13);
}

}  // namespace
}  // namespace stride
