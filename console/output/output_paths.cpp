#include "console/output/output_paths.hpp"

#include <unistd.h>

#include <filesystem>
#include <system_error>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride::console {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& flag, const std::string& path, const std::string& why) {
  throw Error(flag + ": cannot write " + quote(path) + ": " + why);
}

// The folder a new entry `path` would go into ("." for a bare name).
fs::path folder_of(const fs::path& path) {
  const fs::path parent = path.lexically_normal().parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

void check_writable_folder(const std::string& flag, const std::string& path,
                           const fs::path& folder) {
  std::error_code ec;
  if (!fs::exists(folder, ec))
    refuse(flag, path, "folder " + quote(folder.string()) + " does not exist");
  if (!fs::is_directory(folder, ec))
    refuse(flag, path, quote(folder.string()) + " is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    refuse(flag, path, "folder " + quote(folder.string()) + " is not writable");
}

}  // namespace

void check_output_file(const std::string& flag, const std::string& path) {
  if (path.empty()) refuse(flag, path, "empty path");
  const fs::path p(path);
  std::error_code ec;
  if (fs::is_directory(p, ec)) refuse(flag, path, "it is a folder");
  if (!p.has_filename()) refuse(flag, path, "expected a file name");
  check_writable_folder(flag, path, folder_of(p));
  if (fs::exists(p, ec) && ::access(p.c_str(), W_OK) != 0)
    refuse(flag, path, "the file is not writable");
}

void check_output_dir(const std::string& flag, const std::string& path) {
  if (path.empty()) refuse(flag, path, "empty path");
  const fs::path p = fs::path(path).lexically_normal();
  std::error_code ec;
  if (fs::exists(p, ec)) {
    if (!fs::is_directory(p, ec)) refuse(flag, path, "it exists and is not a folder");
    if (::access(p.c_str(), W_OK | X_OK) != 0) refuse(flag, path, "the folder is not writable");
    return;
  }
  // "out/" normalises to "out/" with an empty file name: its folder is out's parent.
  const fs::path leaf = p.has_filename() ? p : p.parent_path();
  check_writable_folder(flag, path, folder_of(leaf));
}

void make_output_dir(const std::string& flag, const std::string& path) {
  check_output_dir(flag, path);
  std::error_code ec;
  if (fs::is_directory(path, ec)) return;
  if (!fs::create_directory(path, ec) || ec) refuse(flag, path, ec ? ec.message() : "not created");
}

}  // namespace stride::console
