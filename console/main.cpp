// `stride`: the single entry point. Subcommand names dispatch through console/cli/subcommands.cpp;
// anything else opens the console (REPL, --script, -c) on an optional scene.
#include <iostream>
#include <string>
#include <vector>

#include "console/cli/subcommand.hpp"
#include "console/repl/console_entry.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto& table = stride::cli::subcommands();
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << "usage: stride <command> [arguments]\n";
    for (const auto& s : table) std::cout << "  " << s.summary << "\n";
    std::cout << stride::console::console_usage();
    return 0;
  }
  if (!args.empty())
    for (const auto& s : table)
      if (s.name == args[0])
        return s.run(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
  return stride::console::console_main(args, std::cout, std::cerr);
}
