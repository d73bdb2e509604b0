#pragma once
// Reading the checkout's documentation pages for the docs tests.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace stride::test_support {

inline std::filesystem::path source_dir() {
  return STRIDE_SOURCE_DIR;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace stride::test_support
