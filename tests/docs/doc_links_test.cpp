// The README is a short front page whose links all lead somewhere: every relative link of
// README.md and docs/*.md names a file that exists and, with #anchor, a heading of that page; each
// docs page opens with an example.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <set>
#include <vector>

#include "tests/docs/doc_files.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::read_text;
using test_support::source_dir;

std::vector<fs::path> pages() {
  std::vector<fs::path> all = {source_dir() / "README.md"};
  for (const auto& e : fs::directory_iterator(source_dir() / "docs"))
    if (e.path().extension() == ".md") all.push_back(e.path());
  std::sort(all.begin(), all.end());
  return all;
}

// GitHub's anchor of a heading: lower case, punctuation dropped, spaces to hyphens.
std::string slug(const std::string& heading) {
  std::string s;
  for (const char c : heading) {
    const auto u = static_cast<unsigned char>(c);
    if (std::isalnum(u) || c == '_' || c == '-')
      s += static_cast<char>(std::tolower(u));
    else if (c == ' ')
      s += '-';
  }
  return s;
}

std::set<std::string> anchors(const fs::path& page) {
  std::set<std::string> out;
  static const std::regex heading("(^|\n)#+ ([^\n]*)");
  const std::string text = read_text(page);
  for (std::sregex_iterator it(text.begin(), text.end(), heading), end; it != end; ++it)
    out.insert(slug((*it)[2].str()));
  return out;
}

TEST(DocLinks, EveryRelativeLinkResolves) {
  static const std::regex link(R"(\]\(([^)#\s]*)(#[^)\s]*)?\))");
  int checked = 0;
  for (const fs::path& page : pages()) {
    const std::string text = read_text(page);
    for (std::sregex_iterator it(text.begin(), text.end(), link), end; it != end; ++it) {
      const std::string target = (*it)[1].str();
      const std::string anchor = (*it)[2].matched ? (*it)[2].str().substr(1) : "";
      if (target.find("://") != std::string::npos) continue;
      const fs::path file = target.empty() ? page : page.parent_path() / target;
      ++checked;
      ASSERT_TRUE(fs::exists(file)) << page.filename() << " links to missing " << target;
      if (!anchor.empty()) {
        EXPECT_TRUE(anchors(file).count(anchor))
            << page.filename() << " links to #" << anchor << " which " << target << " lacks";
      }
    }
  }
  EXPECT_GE(checked, 30);
}

TEST(DocLinks, ReadmeIsAShortFrontPageLinkingEveryDocsPage) {
  const std::string readme = read_text(source_dir() / "README.md");
  EXPECT_LT(std::count(readme.begin(), readme.end(), '\n'), 150);
  for (const char* must : {"bash .ci/demo", "bash .ci/run", "## How do I", "realtime on", "push ",
                           "engine=mujoco", "--connect", "stride view", "docs/images/"})
    EXPECT_NE(readme.find(must), std::string::npos) << must;
  for (const fs::path& page : pages()) {
    if (page.filename() == "README.md") continue;
    EXPECT_NE(readme.find("docs/" + page.filename().string()), std::string::npos)
        << "README does not link " << page.filename();
  }
}

// After its title and before any prose, a page shows what to type (a fenced or indented block).
TEST(DocLinks, EveryDocsPageOpensWithAnExample) {
  for (const fs::path& page : pages()) {
    if (page.filename() == "README.md") continue;
    const std::string text = read_text(page);
    ASSERT_EQ(text.rfind("# ", 0), 0u) << page.filename();
    const auto body = text.find_first_not_of('\n', text.find('\n'));
    ASSERT_NE(body, std::string::npos) << page.filename();
    const bool example = text.compare(body, 3, "```") == 0 || text.compare(body, 4, "    ") == 0;
    EXPECT_TRUE(example) << page.filename() << " does not open with an example";
  }
}

}  // namespace
}  // namespace stride
