// Every thesis equation the code implements is one grep away: tests/docs/equations.txt lists each
// with the file whose line computes it, that file carries `// Eq. N` there, every such tag in the
// source tree is listed, and nothing in the source tree cites a range of equations.
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/docs/doc_files.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::read_text;
using test_support::source_dir;

const char* const kFolders[] = {"robot", "behaviours", "simulator", "console", "bench"};
const std::string kNum = R"((?:[A-D]|\d+)\.\d+)";

struct Tag {
  std::string equation, file;
  int line = 0;
  bool floating = false;  // an own-line tag with no code below it
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  return a == std::string::npos ? "" : s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

bool is_cpp(const fs::path& p) {
  return p.extension() == ".cpp" || p.extension() == ".hpp" || p.extension() == ".h";
}

bool is_text(const fs::path& p) {
  static const std::set<std::string> kText = {".cpp",  ".hpp", ".h",   ".md",   ".js",   ".py",
                                              ".html", ".txt", ".xml", ".json", ".cmake"};
  return kText.count(p.extension().string()) > 0;
}

std::vector<fs::path> source_files() {
  std::vector<fs::path> out;
  for (const char* folder : kFolders)
    for (const auto& e : fs::recursive_directory_iterator(source_dir() / folder))
      if (e.is_regular_file() && is_text(e.path())) out.push_back(e.path());
  return out;
}

// The equations a `//` comment tags: its text starts with "Eq. N", perhaps ", Eq. M" more.
std::vector<std::string> tagged(const std::string& comment) {
  static const std::regex head("^Eq\\. (" + kNum + ")((?:(?:,| and) Eq\\. " + kNum + ")*)");
  static const std::regex num(kNum);
  std::smatch m;
  if (!std::regex_search(comment, m, head)) return {};
  std::vector<std::string> out = {m[1].str()};
  const std::string rest = m[2].str();
  for (std::sregex_iterator i(rest.begin(), rest.end(), num), end; i != end; ++i)
    out.push_back(i->str());
  return out;
}

std::string comment_of(const std::string& line) {
  const auto k = line.find("//");
  return k == std::string::npos ? "" : trimmed(line.substr(k + 2));
}

// Tags of one C++ file: trailing a code line, or on their own line opening a comment block (a
// wrapped sentence that happens to start a line with "Eq." is prose, not a tag).
std::vector<Tag> tags_in(const std::string& file, const std::vector<std::string>& lines) {
  std::vector<Tag> out;
  for (size_t i = 0; i < lines.size(); ++i) {
    const auto k = lines[i].find("//");
    if (k == std::string::npos) continue;
    const std::vector<std::string> eqs = tagged(comment_of(lines[i]));
    if (eqs.empty()) continue;
    const bool own_line = trimmed(lines[i].substr(0, k)).empty();
    bool floating = false;
    if (own_line) {
      const std::string prev = i > 0 ? trimmed(lines[i - 1]) : "";
      if (prev.rfind("//", 0) == 0 && tagged(comment_of(prev)).empty()) continue;
      size_t j = i + 1;
      while (j < lines.size() && trimmed(lines[j]).rfind("//", 0) == 0) ++j;
      floating = j >= lines.size() || trimmed(lines[j]).empty();
    }
    for (const std::string& e : eqs) out.push_back({e, file, static_cast<int>(i + 1), floating});
  }
  return out;
}

// "Eqs.", "Eq. 4.12-4.13", "Eq. 4.8 / 4.12", "Eq. 3.1, 3.2", "Eq. 7.16 to Eq. 7.20": each equation
// gets its own "Eq." so that a grep for any one of them finds it.
bool cites_range(const std::string& line) {
  static const std::regex range("\\bEqs\\b|\\bEq\\.\\s*" + kNum +
                                "\\s*(?:-|–|—|/|,|\\+|and\\b|or\\b|to\\b)\\s*" + kNum +
                                "|\\bto Eq\\.");
  return std::regex_search(line, range);
}

std::set<std::pair<std::string, std::string>> listed_equations() {
  std::set<std::pair<std::string, std::string>> out;
  for (const std::string& raw : lines_of(read_text(source_dir() / "tests/docs/equations.txt"))) {
    const std::string l = trimmed(raw);
    if (l.empty() || l[0] == '#') continue;
    std::istringstream in(l);
    std::string eq, file;
    in >> eq >> file;
    out.insert({eq, file});
  }
  return out;
}

std::vector<Tag> all_tags() {
  std::vector<Tag> out;
  for (const fs::path& p : source_files()) {
    if (!is_cpp(p)) continue;
    const std::string rel = fs::relative(p, source_dir()).generic_string();
    for (const Tag& t : tags_in(rel, lines_of(read_text(p)))) out.push_back(t);
  }
  return out;
}

TEST(EquationTags, EveryListedEquationIsTaggedWhereTheListSays) {
  const auto listed = listed_equations();
  ASSERT_GE(listed.size(), 50u) << "tests/docs/equations.txt lost its entries";
  std::set<std::pair<std::string, std::string>> found;
  for (const Tag& t : all_tags()) found.insert({t.equation, t.file});
  for (const auto& [eq, file] : listed)
    EXPECT_TRUE(found.count({eq, file}))
        << "Eq. " << eq << ": no `// Eq. " << eq << "` tag at a computing line of " << file;
}

TEST(EquationTags, EveryTagIsListedAndSitsOnCode) {
  const auto listed = listed_equations();
  for (const Tag& t : all_tags()) {
    EXPECT_TRUE(listed.count({t.equation, t.file}))
        << t.file << ":" << t.line << ": tags Eq. " << t.equation
        << " but tests/docs/equations.txt has no line \"" << t.equation << " " << t.file << "\"";
    EXPECT_FALSE(t.floating) << t.file << ":" << t.line << ": the tag of Eq. " << t.equation
                             << " has no code below it (tag the line that computes it)";
  }
}

TEST(EquationTags, NoCommentOrTextCitesARange) {
  int files = 0;
  for (const fs::path& p : source_files()) {
    ++files;
    const std::vector<std::string> lines = lines_of(read_text(p));
    for (size_t i = 0; i < lines.size(); ++i)
      EXPECT_FALSE(cites_range(lines[i]))
          << fs::relative(p, source_dir()).generic_string() << ":" << i + 1
          << ": cites a range of equations; write one \"Eq. N\" per equation: " << lines[i];
  }
  EXPECT_GT(files, 100);
}

TEST(EquationTags, TheCheckersSeeWhatTheyShould) {
  const std::vector<std::string> code = {
      "  x = a * b;  // Eq. 4.5 with u_k = 0",    // trailing: a tag
      "  // Eq. 4.1",                             // own line opening a block: a tag
      "  // Eq. 4.2: both axes",                  // after a tag: a tag
      "  y = c;",                                 //
      "  // A sentence that wraps before",        //
      "  // Eq. 7.13 is prose.",                  // wrapped prose: no tag
      "  z = d;  // the law of Eq. 5.6",          // a citation, not a tag
      "  w = e;  // Eq. 4.8, Eq. 4.12 (ankle)"};  // one line, two equations
  std::vector<std::string> seen;
  for (const Tag& t : tags_in("f.cpp", code)) seen.push_back(t.equation);
  EXPECT_EQ(seen, (std::vector<std::string>{"4.5", "4.1", "4.2", "4.8", "4.12"}));
  const std::vector<std::string> floating = {"// Eq. C.14: the choice of C", ""};
  ASSERT_EQ(tags_in("f.cpp", floating).size(), 1u);
  EXPECT_TRUE(tags_in("f.cpp", floating)[0].floating);
  for (const char* r : {"Eqs. 4.1-4.2", "(Eq. 4.12-4.13)", "Eq. 4.8 / 4.12", "Eq. 3.1, 3.2",
                        "Eq. C.16–C.20", "Eq. 7.16 to Eq. 7.20", "Eqs 7.13 and 7.30"})
    EXPECT_TRUE(cites_range(r)) << r;
  for (const char* ok : {"Eq. 4.8, Eq. 4.12 (ankle)", "Eq. 7.13 and Eq. 7.30", "Sec. 7.3.1",
                         "Eq. 3.9, t_0 = T_step", "(Eq. 7.13), 2.5 m"})
    EXPECT_FALSE(cites_range(ok)) << ok;
}

}  // namespace
}  // namespace stride
