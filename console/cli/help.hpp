#pragma once
// `stride help [word]`, `stride <command> --help`: one place that knows both the subcommands and
// the console's commands and keys.
#include <iosfwd>
#include <string>

#include "console/cli/subcommand.hpp"

namespace stride::cli {

// Everything, or what `word` finds among subcommands, console commands and keys.
int help_main(Args args, std::ostream& out);
// `stride <name> --help`: a subcommand's usage, a console command's usage (`stride run` is
// both), or false for a name that is neither.
bool print_command_help(const std::string& name, std::ostream& out);

}  // namespace stride::cli
