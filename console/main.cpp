// `stride`: the single entry point. Subcommand names dispatch through console/cli/subcommands.cpp;
// anything else opens the console (REPL, --script, -c) on an optional scene.
#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "console/cli/help.hpp"
#include "console/cli/subcommand.hpp"
#include "console/repl/console_entry.hpp"

namespace {

int dispatch(const std::vector<std::string>& args);

// Standard output is an output like any other: a full disk or /dev/full under `>` is an error
// and a non-zero exit, not a report nobody can read.
int checked_exit(int status) {
  std::cout.flush();
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout) {
    std::cerr << "stride: cannot write standard output: " << std::strerror(errno) << "\n";
    return status == 0 ? 1 : status;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    return checked_exit(dispatch(args));
  } catch (const std::bad_alloc&) {
    std::cerr << "stride: out of memory\n";
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {  // a path the system refuses
    std::cerr << "stride: " << e.what() << "\n";
    return 1;
  }
}

namespace {

int dispatch(const std::vector<std::string>& args) {
  const auto& table = stride::cli::subcommands();
  const auto is_help = [](const std::string& a) {
    return a == "--help" || a == "-h" || a == "help";
  };
  if (!args.empty() && is_help(args[0]))
    return stride::cli::help_main(std::span<const std::string>(args).subspan(1), std::cout);
  const auto wants_help = [&] {
    return (args.size() == 2 && is_help(args[1])) ||
           std::any_of(args.begin() + 1, args.end(),
                       [](const std::string& a) { return a == "--help" || a == "-h"; });
  };
  // `stride run --help`, `stride experiment posture --help`, `stride mr --help`
  if (!args.empty() && wants_help() && stride::cli::print_command_help(args[0], std::cout))
    return 0;
  if (!args.empty())
    for (const auto& s : table)
      if (s.name == args[0])
        return s.run(std::span<const std::string>(args).subspan(1), std::cout, std::cerr);
  return stride::console::console_main(args, std::cout, std::cerr);
}

}  // namespace
