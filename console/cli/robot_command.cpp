// `stride robot ...`: starts `stride-robot` (built next to `stride`), the robot runtime that links
// only robot/ and behaviours/: the same binary a NAO runs, tested here against the simulator.
// `stride lola dump ...` runs the packet tool in this process.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ostream>
#include <vector>

#include "console/cli/subcommand.hpp"
#include "console/system/child_process.hpp"
#include "robot/app/robot_main.hpp"

namespace stride::cli {

int robot_main(Args args, std::ostream& out, std::ostream& err) {
  const std::string robot = console::sibling_executable("stride-robot");
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
