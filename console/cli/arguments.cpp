#include "console/cli/arguments.hpp"

#include <algorithm>
#include <ostream>

#include "behaviours/module_catalogue.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/quote.hpp"

namespace stride::cli {

bool asks_for_settings(Args args) {
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--set" && args[i + 1] == "?") return true;
  return false;
}

void print_module_parameters(std::ostream& out) {
  ModuleRegistry registry;
  behaviours::register_all_modules(registry);
  out << "module parameters (--set Module.field=value; default [unit] in [range]):\n";
  for (const auto& line : parameter_lines(registry)) out << "  " << line << "\n";
}

ArgumentReader::ArgumentReader(Args args, std::string command)
    : args_(args), command_(std::move(command)) {}

int ArgumentReader::find(const std::string& flag) const {
  for (size_t i = 0; i < args_.size(); ++i)
    if (args_[i] == flag) return static_cast<int>(i);
  return -1;
}

std::string ArgumentReader::positional(const char* what) {
  for (size_t i = 0; i < args_.size(); ++i) {
    if (used_.count(static_cast<int>(i))) continue;
    if (args_[i].rfind("--", 0) == 0) {
      ++i;  // skip the flag's value
      continue;
    }
    used_.insert(static_cast<int>(i));
    return args_[i];
  }
  throw UsageError("stride " + command_ + ": missing <" + what + ">");
}

bool ArgumentReader::has(const std::string& flag) const {
  return find(flag) >= 0;
}

bool ArgumentReader::flag(const std::string& flag) {
  const int i = find(flag);
  if (i < 0) return false;
  used_.insert(i);
  return true;
}

std::string ArgumentReader::text(const std::string& flag) {
  const int i = find(flag);
  if (i < 0) throw UsageError("stride " + command_ + ": missing " + flag);
  if (i + 1 >= static_cast<int>(args_.size()))
    throw UsageError("stride " + command_ + ": " + flag + ": expected a value after it");
  used_.insert(i);
  used_.insert(i + 1);
  return args_[i + 1];
}

std::string ArgumentReader::text_or(const std::string& flag, const std::string& fallback) {
  return has(flag) ? text(flag) : fallback;
}

std::vector<std::string> ArgumentReader::texts(const std::string& flag) {
  std::vector<std::string> values;
  for (size_t i = 0; i < args_.size(); ++i) {
    if (args_[i] != flag || used_.count(static_cast<int>(i))) continue;
    if (i + 1 >= args_.size())
      throw UsageError("stride " + command_ + ": " + flag + ": expected a value after it");
    used_.insert(static_cast<int>(i));
    used_.insert(static_cast<int>(i + 1));
    values.push_back(args_[++i]);
  }
  return values;
}

double ArgumentReader::number(const std::string& flag) {
  try {
    return parse_number(text(flag), "stride " + command_ + ": " + flag);
  } catch (const Error& e) {
    throw UsageError(e.what());  // a malformed value is a wrong command line
  }
}

double ArgumentReader::number_or(const std::string& flag, double fallback) {
  return has(flag) ? number(flag) : fallback;
}

std::uint64_t ArgumentReader::unsigned_integer(const std::string& flag) {
  try {
    return parse_unsigned(text(flag), "stride " + command_ + ": " + flag);
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
}

void ArgumentReader::only(std::initializer_list<std::string_view> known) const {
  for (const std::string& a : args_)
    if (a.rfind("--", 0) == 0 && std::find(known.begin(), known.end(), a) == known.end())
      throw UsageError("stride " + command_ + ": unknown argument " + quote(a));
}

void ArgumentReader::finish() const {
  for (size_t i = 0; i < args_.size(); ++i)
    if (!used_.count(static_cast<int>(i)))
      throw UsageError("stride " + command_ + ": " +
                       (args_[i].rfind("--", 0) == 0 ? "unknown" : "unexpected") + " argument " +
                       quote(args_[i]));
}

}  // namespace stride::cli
