// `stride`: the single entry point. Subcommands dispatch through console/cli/subcommands.cpp.
#include <iostream>
#include <string>
#include <vector>

#include "console/cli/subcommand.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto& table = stride::cli::subcommands();
  if (args.empty() || args[0] == "--help" || args[0] == "-h") {
    std::cout << "usage: stride <command> [arguments]\n";
    for (const auto& s : table) std::cout << "  " << s.summary << "\n";
    return args.empty() ? 2 : 0;
  }
  for (const auto& s : table)
    if (s.name == args[0])
      return s.run(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
  std::cerr << "stride: unknown command '" << args[0] << "' (see stride --help)\n";
  return 2;
}
