#pragma once
// The committed seed inputs of a fuzz target, sorted by content so runs are repeatable.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace stride::test {

// Every file in <source dir>/<relative_dir>.
inline std::vector<std::string> read_corpus(const std::string& relative_dir) {
  std::vector<std::string> out;
  const auto dir = std::filesystem::path(STRIDE_SOURCE_DIR) / relative_dir;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    out.push_back(ss.str());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace stride::test
