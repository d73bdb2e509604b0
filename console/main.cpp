// `stride`: the single entry point. Subcommand names dispatch through console/cli/subcommands.cpp;
// anything else opens the console (REPL, --script, -c) on an optional scene.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "console/cli/subcommand.hpp"
#include "console/repl/console_entry.hpp"

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const auto& table = stride::cli::subcommands();
  const auto is_help = [](const std::string& a) {
    return a == "--help" || a == "-h" || a == "help";
  };
  if (!args.empty() && is_help(args[0])) {
    std::cout << "usage: stride <command> [arguments]\n";
    for (const auto& s : table) std::cout << "  " << s.summary << "\n";
    std::cout << stride::console::console_usage();
    return 0;
  }
  if (!args.empty())
    for (const auto& s : table)
      if (s.name == args[0]) {
        // `stride run --help`, `stride experiment posture --help`: the subcommand's usage line
        const bool wants_help = (args.size() == 2 && is_help(args[1])) ||
                                std::any_of(args.begin() + 1, args.end(), [](const std::string& a) {
                                  return a == "--help" || a == "-h";
                                });
        if (wants_help) {
          std::cout << "usage: stride " << s.summary << "\n";
          return 0;
        }
        return s.run(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
      }
  return stride::console::console_main(args, std::cout, std::cerr);
}
