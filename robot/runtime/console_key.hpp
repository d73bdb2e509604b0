#pragma once
// The console's framework keys, "representation:<Name>[.path]" and "module:<Name>[.path]": parsed
// in one place for the runtime, the debug server and the console's remote target.
#include <string>
#include <string_view>

namespace stride {

struct ConsoleKey {
  bool representation = false;  // false: a module's parameters
  std::string name;
  std::string path;  // "" = the whole value; "position[3]", "cop.x", "[2]"
  std::string root() const { return (representation ? "representation:" : "module:") + name; }
};

// Throws stride::Error naming the key when it is neither form or has no name.
ConsoleKey split_console_key(std::string_view key);

}  // namespace stride
