// `stride robot ...`: starts `stride-robot` (built next to `stride`), the robot runtime that links
// only robot/ and behaviours/: the same binary a NAO runs, tested here against the simulator.
// `stride lola dump ...` runs the packet tool in this process.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <vector>

#include "console/cli/subcommand.hpp"
#include "robot/app/robot_main.hpp"

namespace stride::cli {

int robot_main(Args args, std::ostream& out, std::ostream& err) {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  const std::string robot = (self.parent_path() / "stride-robot").string();
  std::vector<std::string> words{robot};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  out.flush();
  ::execv(robot.c_str(), argv.data());  // returns only on failure
  err << "stride robot: cannot start " << robot << " (" << std::strerror(errno)
      << "): build the stride-robot target" << std::endl;
  return 1;
}

int lola_main(Args args, std::ostream& out, std::ostream& err) {
  return stride::lola_main(args, out, err);
}

}  // namespace stride::cli
