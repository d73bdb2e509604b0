#pragma once
// The console's vocabulary (docs/architecture.md "Console"): name, usage, arity and an argument
// check per command. Pure data and checks: no simulation is needed to parse, so the parser can be
// fuzzed.
#include <string>
#include <string_view>
#include <vector>

#include "console/interpreter/help_search.hpp"
#include "robot/framework/module.hpp"

namespace stride::console {

using Words = std::vector<std::string>;

struct CommandSpec {
  std::string_view name;
  std::string_view usage;  // e.g. "run [seconds]"
  std::string_view summary;
  int min_args = 0;
  int max_args = 0;  // -1: any number
  // Throws stride::Error naming the bad argument; called only with an allowed argument count.
  void (*check)(const Words& args) = nullptr;
};

const std::vector<CommandSpec>& command_table();

// `help [word]`: every command and key namespace, or what `word` finds (console/interpreter/
// help_search.hpp: a command's name first, then whole words, then any part); "keys" lists the
// key namespaces.
std::string help_text(const std::string& word);
// The entries help searches (commands, then keys) and the listing of some of them by index.
std::vector<HelpEntry> help_entries();
std::string help_listing(const std::vector<std::size_t>& entries);

// The key namespaces get, set, watch, plot, expect and wait take.
struct KeySpec {
  std::string_view pattern;  // e.g. "provider:X"
  std::string_view summary;
};
const std::vector<KeySpec>& key_table();
const CommandSpec* find_command(std::string_view name);  // nullptr if unknown
std::vector<std::string> command_names();

// `video start <dir> [view] [fps N]` read once for both the check and the command.
struct VideoStart {
  std::string dir, view;  // view empty: the default view
  long long fps = 25;
};
VideoStart parse_video_start(const Words& args);  // args[0] == "start"; throws stride::Error
DebugSwitch parse_debug_switch(const std::string& word);  // on|off|quiet

// Keys the console reads: representation:X[.path], module:X[.path], sim.*, robot.*, log.*.
bool is_value_key(std::string_view key);
bool is_framework_key(std::string_view key);  // representation:X or module:X, with a name

}  // namespace stride::console
