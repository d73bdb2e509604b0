#include "robot/core/data_dir.hpp"

#include <cstdlib>
#include <vector>

#include "robot/core/error.hpp"

namespace stride {

namespace fs = std::filesystem;

namespace {

bool holds_scenes(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "scenes", ec);
}

fs::path executable_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe.parent_path();
}

}  // namespace

fs::path data_dir() {
  if (const char* env = std::getenv("STRIDE_DATA"); env && *env) {
    if (!holds_scenes(env))
      throw InputError("STRIDE_DATA='" + std::string(env) + "' has no scenes/ directory");
    return fs::path(env);
  }
  std::vector<fs::path> tried;
  if (const fs::path exe = executable_dir(); !exe.empty())
    tried.push_back((exe / ".." / "share" / "stride").lexically_normal());
  tried.emplace_back(STRIDE_BUILD_DATA_DIR);  // the build tree: the checkout it was built from
  for (const auto& dir : tried)
    if (holds_scenes(dir)) return dir;
  std::string list;
  for (const auto& dir : tried) list += (list.empty() ? "" : ", ") + dir.string();
  throw InputError("no data directory with scenes/ (looked in " + list + "; set STRIDE_DATA)");
}

std::string data_file(const std::string& relative) {
  return (data_dir() / relative).string();
}

std::string find_input(const std::string& path) {
  std::error_code ec;
  if (path.empty() || fs::exists(path, ec) || fs::path(path).is_absolute()) return path;
  try {
    const fs::path shipped = data_dir() / path;
    if (fs::exists(shipped, ec)) return shipped.string();
  } catch (const Error&) {
    // no data directory: the caller reports the path as given
  }
  return path;
}

std::string data_dir_line() {
  try {
    return "data directory: " + data_dir().string() + " (STRIDE_DATA overrides)";
  } catch (const Error& e) {
    return std::string("data directory: ") + e.what();
  }
}

}  // namespace stride
