#include "console/plot/figure_folder.hpp"

#include <filesystem>
#include <system_error>

#include "robot/core/error.hpp"

namespace stride::plot {

void make_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error("cannot create directory '" + dir + "': " + ec.message());
}

std::string figure_dir(const std::string& out_dir, const std::string& family) {
  const std::string dir = (std::filesystem::path(out_dir) / "figures" / family).string();
  make_directory(dir);
  return dir;
}

std::string figure_stem(const std::string& out_dir, const std::string& family,
                        const std::string& name) {
  return (std::filesystem::path(figure_dir(out_dir, family)) / name).string();
}

}  // namespace stride::plot
