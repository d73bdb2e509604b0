#pragma once
// Reading `--flag value` command lines strictly: unknown flags and bad values are one-line errors.
#include <cstdint>
#include <initializer_list>
#include <iosfwd>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "console/cli/subcommand.hpp"

namespace stride::cli {

// `--set ?` anywhere: the command lists what --set can change instead of running.
bool asks_for_settings(Args args);
// `--set ?` for module parameters: every module's fields with default, unit and range.
void print_module_parameters(std::ostream& out);

class ArgumentReader {
 public:
  ArgumentReader(Args args, std::string command);

  std::string positional(const char* what);  // next non-flag argument, required
  bool has(const std::string& flag) const;
  bool flag(const std::string& flag);  // a flag without value
  std::string text(const std::string& flag);
  std::string text_or(const std::string& flag, const std::string& fallback);
  std::vector<std::string> texts(const std::string& flag);  // every `flag value`, in order
  double number(const std::string& flag);
  double number_or(const std::string& flag, double fallback);
  std::uint64_t unsigned_integer(const std::string& flag);
  // Throws for a `--flag` not in `known` (before any other error, so the line names it).
  void only(std::initializer_list<std::string_view> known) const;
  // Throws if anything was not consumed.
  void finish() const;

 private:
  int find(const std::string& flag) const;
  Args args_;
  std::string command_;
  std::set<int> used_;
};

}  // namespace stride::cli
