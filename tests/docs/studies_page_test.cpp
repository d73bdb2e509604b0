// docs/studies.md stays the one place a thesis study is found from: every path it names exists,
// every study library in console/experiments/ is named there, and each chapter's section names
// the command that runs the study and the tests that hold it.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "tests/docs/doc_files.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::read_text;
using test_support::source_dir;

std::string page() {
  return read_text(source_dir() / "docs/studies.md");
}

// The `code` spans of the page that are paths into the checkout (a folder/ or a file.ext).
std::vector<std::string> named_paths(const std::string& text) {
  static const std::regex span("`([A-Za-z_]+/[A-Za-z0-9_./-]*)`");
  std::vector<std::string> out;
  for (std::sregex_iterator i(text.begin(), text.end(), span), end; i != end; ++i) {
    const std::string p = (*i)[1].str();
    if (p.back() == '/' || p.find('.') != std::string::npos) out.push_back(p);
  }
  return out;
}

TEST(StudiesPage, EveryNamedPathExists) {
  const std::vector<std::string> paths = named_paths(page());
  EXPECT_GT(paths.size(), 20u);
  for (const std::string& p : paths)
    EXPECT_TRUE(fs::exists(source_dir() / p)) << "docs/studies.md names `" << p << "`";
}

TEST(StudiesPage, NamesEveryStudyLibrary) {
  const std::string text = page();
  static const std::regex study(R"(_(study|analyses|experiment|figures)\.cpp$)");
  int found = 0;
  for (const auto& e : fs::directory_iterator(source_dir() / "console/experiments")) {
    const std::string name = e.path().filename().string();
    if (!std::regex_search(name, study)) continue;
    ++found;
    EXPECT_NE(text.find(name), std::string::npos)
        << "docs/studies.md does not name console/experiments/" << name;
  }
  EXPECT_GE(found, 8);
}

TEST(StudiesPage, EachChapterNamesItsCommandAndTests) {
  const std::string text = page();
  int chapters = 0;
  for (std::size_t at = text.find("\n## Ch. "); at != std::string::npos;
       at = text.find("\n## Ch. ", at + 1)) {
    const std::size_t end = text.find("\n## ", at + 1);
    const std::string section = text.substr(at, end == std::string::npos ? end : end - at);
    const std::string title = section.substr(1, section.find('\n', 1) - 1);
    EXPECT_NE(section.find("`stride "), std::string::npos) << title << ": no command";
    EXPECT_NE(section.find("tests/"), std::string::npos) << title << ": no tests";
    ++chapters;
  }
  EXPECT_EQ(chapters, 6);  // Ch. 2 to Ch. 7
}

}  // namespace
}  // namespace stride
