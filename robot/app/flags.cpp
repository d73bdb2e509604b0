#include "robot/app/flags.hpp"

#include "robot/core/error.hpp"

namespace stride {

Flags read_flags(std::span<const std::string> args, std::initializer_list<std::string_view> flags,
                 const std::string& command) {
  Flags out;
  std::string known;
  for (auto f : flags) known += (known.empty() ? "" : ", ") + std::string(f);
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (!a.starts_with("--")) {
      out.positional.push_back(a);
      continue;
    }
    bool ok = false;
    for (auto f : flags) ok = ok || f == a;
    if (!ok) throw Error(command + ": unknown option '" + a + "' (expected " + known + ")");
    if (i + 1 >= args.size()) throw Error(command + ": " + a + ": expected a value after it");
    if (!out.values.emplace(a, args[i + 1]).second)
      throw Error(command + ": " + a + ": given twice");
    ++i;
  }
  return out;
}

}  // namespace stride
