// docs/architecture.md is true to the tree: every folder it names exists, and every folder of the
// code (robot/*, simulator/*, behaviours/*, console/*) is named in it.
#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "tests/docs/doc_files.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using test_support::read_text;
using test_support::source_dir;

// Backquoted paths below a top-level folder of the checkout, e.g. `robot/debug/`.
std::set<std::string> named_paths(const std::string& page) {
  static const std::regex path(
      "`((robot|simulator|behaviours|console|scenes|tests|bench|docs|"
      "cmake)/[A-Za-z0-9_./-]*)`");
  std::set<std::string> found;
  for (std::sregex_iterator it(page.begin(), page.end(), path), end; it != end; ++it)
    found.insert((*it)[1].str());
  return found;
}

TEST(ArchitecturePage, EveryNamedPathExists) {
  const std::string page = read_text(source_dir() / "docs/architecture.md");
  const auto paths = named_paths(page);
  ASSERT_GE(paths.size(), 40u) << "the page names the folders it describes";
  for (const std::string& p : paths) {
    const fs::path full = source_dir() / p;
    if (p.back() == '/')
      EXPECT_TRUE(fs::is_directory(full))
          << "docs/architecture.md names `" << p << "`, which is not a folder";
    else
      EXPECT_TRUE(fs::exists(full))
          << "docs/architecture.md names `" << p << "`, which does not exist";
  }
}

TEST(ArchitecturePage, EveryCodeFolderIsNamed) {
  const std::string page = read_text(source_dir() / "docs/architecture.md");
  const auto paths = named_paths(page);
  int folders = 0;
  for (const char* top : {"robot", "simulator", "behaviours", "console"}) {
    EXPECT_TRUE(paths.count(std::string(top) + "/")) << top;
    for (const auto& entry : fs::directory_iterator(source_dir() / top)) {
      if (!entry.is_directory()) continue;
      ++folders;
      const std::string name = std::string(top) + "/" + entry.path().filename().string() + "/";
      EXPECT_TRUE(paths.count(name)) << "docs/architecture.md does not name `" << name << "`";
    }
  }
  EXPECT_GE(folders, 30) << "the walk found the code's folders";
}

// The page says what exists: the debug server, connect and MuJoCo are code, not plans.
TEST(ArchitecturePage, DescribesTheDebugServerAndMujocoAsCode) {
  const std::string page = read_text(source_dir() / "docs/architecture.md");
  EXPECT_EQ(page.find("Not in the code yet"), std::string::npos);
  for (const char* term : {"`connect", "debug server", "MuJoCo", "`stride view`", "`stride tune`"})
    EXPECT_NE(page.find(term), std::string::npos) << term;
}

}  // namespace
}  // namespace stride
