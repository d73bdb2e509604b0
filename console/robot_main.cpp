// `stride-robot`: the program that goes onto a NAO v6 (`stride robot` and the deployment in
// docs/physical-robot.md start it). It links only robot/ and behaviours/: no ODE, no OSMesa,
// no console.
//   stride-robot --config <robot.xml> [--lola <socket>] [--log <file>]
//   stride-robot lola dump [<socket>] [--frames N]
#include <iostream>
#include <string>
#include <vector>

#include "behaviours/module_catalogue.hpp"
#include "robot/app/robot_main.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const std::span<const std::string> all(args);
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
    std::cout << "usage: stride-robot " << stride::kRobotUsage << "\n       stride-robot "
              << stride::kLolaUsage << "\n";
    return 0;
  }
  if (!args.empty() && args[0] == "lola")
    return stride::lola_main(all.subspan(1), std::cout, std::cerr);
  stride::ModuleRegistry registry;
  stride::behaviours::register_all_modules(registry);
  return stride::robot_main(all, registry, std::cout, std::cerr);
}
