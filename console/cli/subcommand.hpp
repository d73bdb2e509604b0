#pragma once
// `stride <subcommand> ...`: each subcommand is a free function listed once in subcommands.cpp.
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace stride::cli {

using Args = std::span<const std::string>;

struct Subcommand {
  std::string_view name;
  std::string_view summary;  // one line for `stride --help`
  int (*run)(Args args, std::ostream& out, std::ostream& err);
};

const std::vector<Subcommand>& subcommands();

}  // namespace stride::cli
