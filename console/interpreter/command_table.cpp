#include "console/interpreter/command_table.hpp"

#include "console/interpreter/help_search.hpp"
#include "console/interpreter/help_topics.hpp"
#include "console/interpreter/sweep_arguments.hpp"
#include "console/interpreter/values.hpp"
#include "robot/core/error.hpp"
#include "robot/core/physical_limits.hpp"
#include "robot/core/quote.hpp"

namespace stride::console {

bool is_framework_key(std::string_view key) {
  for (std::string_view prefix : {"representation:", "module:"})
    if (key.starts_with(prefix) && key.size() > prefix.size() && key[prefix.size()] != '.')
      return true;
  return false;
}

bool is_value_key(std::string_view key) {
  if (is_framework_key(key)) return true;
  for (std::string_view prefix :
       {"sim.", "robot.", "log.", "provider:", "override:", "debug:", "sweep.", "tune."})
    if (key.starts_with(prefix) && key.size() > prefix.size()) return true;
  return false;
}

namespace {

void need_key(const std::string& key, bool framework_only) {
  if (framework_only ? !is_framework_key(key) : !is_value_key(key))
    throw Error(quote(key) + " is not a key (representation:X" +
                std::string(framework_only
                                ? " or module:X)"
                                : ", module:X, sim.*, robot.*, log.*, sweep.*, tune.*, provider:X, "
                                  "override:X, debug:X)"));
}

void check_run(const Words& a) {
  if (!a.empty()) parse_seconds(a[0], "seconds");
}
void check_step(const Words& a) {
  if (!a.empty()) parse_integer(a[0], "frames", 1, 1000000000);
}
void check_on_off(const Words& a) {
  parse_on_off(a[0], "switch");
}
void check_get(const Words& a) {
  need_key(a[0], false);
  if (a.size() == 2 && a[1] != "?") throw Error("second argument must be '?'");
}
void check_set(const Words& a) {
  need_key(a[0], true);
  if (a.size() == 2 && a[1] == "unchanged") {
    if (!a[0].starts_with("representation:"))
      throw Error("'unchanged' releases a representation, not " + quote(a[0]));
    return;
  }
  for (std::size_t i = 1; i < a.size(); ++i)
    if (a[i].find('=') == std::string::npos || a[i].front() == '=')
      throw Error("expected <field>=<value>, got " + quote(a[i]));
}
void check_mr(const Words& a) {
  if (a.size() == 1 && a[0] != "?") throw Error("give a module, default or ?");
}
void check_dr(const Words& a) {
  if (a.size() == 1 && a[0] != "?") throw Error("give on, off or quiet");
  if (a.size() == 2) parse_debug_switch(a[1]);
}
void check_watch(const Words& a) {
  if (a.size() == 1 && a[0] == "off") return;
  std::size_t keys = a.size();
  if (a.size() >= 2 && a[a.size() - 2] == "every") {
    parse_integer(a.back(), "every", 1, 1000000000);
    keys -= 2;
  }
  if (keys == 0) throw Error("give at least one key");
  for (std::size_t i = 0; i < keys; ++i) need_key(a[i], false);
}
void check_plot(const Words& a) {
  if (a.size() == 1 && (a[0] == "stop" || a[0] == "off")) return;
  std::size_t keys = a.size();
  if (a.size() >= 2 && a[a.size() - 2] == "to") keys -= 2;
  if (keys == 0) throw Error("give at least one key");
  for (std::size_t i = 0; i < keys; ++i) need_key(a[i], false);
}
void check_log(const Words& a) {
  const std::string& s = a[0];
  const std::size_t n = a.size() - 1;
  if (s == "stop" || s == "replay" || s == "info") {
    if (n != 0) throw Error("'log " + s + "' takes no arguments");
  } else if (s == "start" || s == "load" || s == "save") {
    if (n != 1) throw Error("'log " + s + "' takes one file");
  } else if (s == "goto") {
    if (n != 1) throw Error("'log goto' takes one frame number");
    parse_integer(a[1], "frame", 0, 1000000000000LL);
  } else if (s == "export") {
    if (n < 2) throw Error("'log export' takes a csv file and at least one key");
  } else {
    throw Error("unknown log action " + quote(s) +
                " (start, stop, save, load, info, goto, export, replay)");
  }
}
void check_push(const Words& a) {
  const char* names[] = {"fx", "fy", "fz"};
  for (int i = 0; i < 3; ++i) parse_bounded(a[i + 1], names[i], limits::kMaxForce, "N");
  if (!(parse_seconds(a[4], "seconds") > 0)) throw Error("seconds: expected > 0");
}
void check_snapshot(const Words& a) {
  if (a[0].size() < 5 || a[0].substr(a[0].size() - 4) != ".png")
    throw Error("expected a file name ending in .png, got " + quote(a[0]));
}
void check_video(const Words& a) {
  if (a[0] == "stop") {
    if (a.size() != 1) throw Error("video stop takes no arguments");
    return;
  }
  if (a[0] != "start") throw Error("expected start or stop, got " + quote(a[0]));
  parse_video_start(a);
}
void check_mv(const Words& a) {
  const char* names[] = {"x", "y", "z", "yaw"};
  for (std::size_t i = 0; i < a.size(); ++i)
    parse_bounded(a[i], names[i], i < 3 ? limits::kMaxPosition : 1e3, i < 3 ? "m" : "rad");
}
void check_sn(const Words& a) {
  if (a[0] != "noise" && a[0] != "delay" && a[0] != "quantise")
    throw Error("expected noise, delay or quantise, got " + quote(a[0]));
  parse_on_off(a[1], a[0]);
}
void check_expect(const Words& a) {
  need_key(a[0], false);
  parse_op(a[1]);
  if (a.size() == 4 && parse_number(a[3], "tolerance") < 0) throw Error("tolerance: expected >= 0");
}
void check_sweep(const Words& a) {
  parse_sweep_arguments(a);
}
void check_tune(const Words& a) {
  parse_sweep_arguments(a, "tune");
}
void check_endpoint(const std::string& text, const char* what) {
  const auto colon = text.rfind(':');
  parse_integer(colon == std::string::npos ? text : text.substr(colon + 1),
                std::string(what) + " port", 0, 65535);
}
void check_connect(const Words& a) {
  check_endpoint(a[0], "connect");
}
void check_serve(const Words& a) {
  if (a[0] == "stop") {
    if (a.size() != 1) throw Error("serve stop takes no arguments");
    return;
  }
  check_endpoint(a[0], "serve");
}
void check_view(const Words& a) {
  if (a.empty()) return;
  if (a[0] == "stop") {
    if (a.size() != 1) throw Error("view stop takes no arguments");
    return;
  }
  check_endpoint(a[0], "view");
}
void check_wait(const Words& a) {
  if (a[0] != "until") throw Error("expected 'until', got " + quote(a[0]));
  if (a.size() == 5) throw Error("give 'timeout <seconds>' after the value");
  check_expect({a[1], a[2], a[3]});
  if (a.size() == 6) {
    if (a[4] != "timeout") throw Error("expected 'timeout', got " + quote(a[4]));
    if (!(parse_seconds(a[5], "timeout") > 0)) throw Error("timeout: expected > 0");
  }
}

}  // namespace

DebugSwitch parse_debug_switch(const std::string& word) {
  if (word == "quiet") return DebugSwitch::Quiet;
  return parse_on_off(word, "dr") ? DebugSwitch::On : DebugSwitch::Off;
}

VideoStart parse_video_start(const Words& a) {
  if (a.size() < 2) throw Error("video start: expected a movie file (.apng, .mp4) or a directory");
  VideoStart v;
  v.dir = a[1];
  std::size_t i = 2;
  if (i < a.size() && a[i] != "fps") v.view = a[i++];
  if (i < a.size()) {
    if (a[i] != "fps" || i + 2 != a.size()) throw Error("expected 'fps <frames per second>' last");
    v.fps = parse_integer(a[i + 1], "fps", 1, 1000);
  }
  return v;
}

// The commands on the scene, its run and its values, in the order help lists them.
std::vector<CommandSpec> simulation_commands() {
  return {
      {"help", "help [pattern]", "list commands (matching pattern)", 0, 1, nullptr},
      {"load", "load <scene.xml>", "load a scene (runs <scene>.con next to it)", 1, 1, nullptr},
      {"reset", "reset", "rebuild the scene from its description", 0, 0, nullptr},
      {"restart", "restart",
       "the scenario from its start, to watch a walk from the beginning: the local simulation "
       "resets (and runs, in the REPL); a connected robot restarts its scenario (stride run "
       "--debug: the scene resets and runs; stride robot: its controller from its configuration)",
       0, 0, nullptr},
      {"run", "run [seconds]", "run the simulation (without seconds: until Ctrl-C)", 0, 1,
       check_run},
      {"step", "step [frames]", "advance by simulation steps (default 1)", 0, 1, check_step},
      {"pause", "pause", "stop running", 0, 0, nullptr},
      {"realtime", "realtime on|off",
       "pace runs to the wall clock (on by default in a terminal; off: as fast as possible, the "
       "prompt then reads 'stride (fast)>')",
       1, 1, check_on_off},
      {"get", "get <key> [?]", "print a value; ? prints the type description", 1, 2, check_get},
      {"set", "set <key> <field>=<value>... | set representation:X unchanged",
       "change fields, all or nothing; a representation's are held every frame until unchanged", 2,
       -1, check_set},
      {"mr", "mr ? | mr <Rep> <Module>|default|?", "module request: choose a provider", 1, 2,
       check_mr},
      {"dr", "dr ? | dr <name> on|off|quiet",
       "debug request: on prints its lines and values (debug:<name>.<value>), quiet only the "
       "values; dr ? lists them",
       1, 2, check_dr},
      {"watch", "watch <key>... [every N] | watch off",
       "print values every N control frames while running (locally and remotely alike)", 1, -1,
       check_watch},
      {"plot", "plot <key>... [to file.csv] | plot stop", "record values; stop writes CSV + PNG", 1,
       -1, check_plot},
      {"log",
       "log start <file>|stop|save <file>|load <file>|info|goto <frame>|export <csv> <key>...|"
       "replay",
       "record, load, browse, export and replay logs; info lists a log's frames, representations "
       "and the providers it was recorded with (replay uses them)",
       1, -1, check_log},
      {"report", "report [file]", "run report (JSON with the state hash if a file is given)", 0, 1,
       nullptr},
  };
}

// The commands on robots, connections, pictures, checks, scripts and studies.
std::vector<CommandSpec> robot_and_tool_commands() {
  return {
      {"push", "push <body> <fx> <fy> <fz> <seconds>", "apply a force (N) to a link", 5, 5,
       check_push},
      {"robot", "robot [<name>|<host:port>|?]",
       "select the robot that robot keys, framework keys, mr, dr, log, push, mv, sn and the "
       "built-in views act on (a scene's robot or a connection); without a name or with ? list "
       "them",
       0, 1, nullptr},
      {"connect", "connect <host:port> [token]",
       "act on a robot's debug server (token: or STRIDE_TOKEN); simulation commands then say "
       "they need a simulation",
       1, 2, check_connect},
      {"disconnect", "disconnect [host:port]",
       "close the connection to a robot and act on the local simulation again", 0, 1, nullptr},
      {"serve", "serve <[host:]port> [token-file] | serve stop",
       "serve the selected robot's controller to other consoles (loopback unless a token is "
       "given, by file or STRIDE_TOKEN)",
       1, 2, check_serve},
      {"view", "view [[host:]port] [token-file] | view stop",
       "the live view in a browser for what the console acts on (default 127.0.0.1:8080, port 0: "
       "any free one; beyond loopback a token is needed, by file or STRIDE_TOKEN)",
       0, 2, check_view},
      {"mv", "mv <x> <y> <z> [yaw]", "move the robot (m, rad)", 3, 4, check_mv},
      {"sn", "sn noise|delay|quantise on|off", "sensor imperfections", 2, 2, check_sn},
      {"snapshot", "snapshot <file.png> [view]",
       "render a picture (views: follow, front, side, top, scene cameras)", 1, 2, check_snapshot},
      {"video", "video start <file.apng|.mp4>|<dir> [view] [fps N] | video stop",
       "record an MP4 movie or numbered PNG frames while running (default 25 fps)", 1, 5,
       check_video},
      {"expect", "expect <key> <op> <value> [tolerance]", "check a value; fails a script", 3, 4,
       check_expect},
      {"wait", "wait until <key> <op> <value> [timeout <seconds>]", "run until a condition holds",
       4, 6, check_wait},
      {"call", "call <file.con>", "run a script", 1, 1, nullptr},
      {"sweep", "sweep <file.xml> [jobs N] [out <dir>] [seeds N] [resume] [overwrite] [quiet]",
       "run a sweep file (as `stride sweep`); its tallies become sweep.<tally>.<column>[<group>] "
       "keys",
       1, 10, check_sweep},
      {"tune", "tune <file.xml> [jobs N] [out <dir>] [resume] [overwrite] [quiet]",
       "run a search over a tuning file (as `stride tune`); its outcome becomes tune.best, "
       "tune.heldout.thesis|tuned[_sd], tune.param.<name> ... keys",
       1, 8, check_tune},
      {"echo", "echo <text>", "print text", 0, -1, nullptr},
      {"quit", "quit", "leave the console", 0, 0, nullptr},
  };
}

const std::vector<CommandSpec>& command_table() {
  static const std::vector<CommandSpec> table = [] {
    std::vector<CommandSpec> all = simulation_commands();
    for (CommandSpec& c : robot_and_tool_commands()) all.push_back(std::move(c));
    return all;
  }();
  return table;
}

const std::vector<KeySpec>& key_table() {
  static const std::vector<KeySpec> table = {
      {"representation:X[.path]",
       "a representation on the blackboard; set holds it every frame until 'set "
       "representation:X unchanged'; joint arrays by name, e.g. .position[LAnklePitch]"},
      {"module:X[.path]", "a module's parameters (get module:X ? lists fields and ranges)"},
      {"provider:X", "the module that provides representation X (mr changes it)"},
      {"override:X", "what set holds on representation X, or (none)"},
      {"debug:<request>.<value>", "a value a debug request shows (dr <request> on|quiet)"},
      {"sim.time|steps|hash", "simulated time [s], physics steps, state hash"},
      {"robot.name|fell", "the selected robot's name; whether it has fallen"},
      {"robot.torso.x|y|z|roll|pitch|yaw", "the selected robot's true torso pose [m, rad]"},
      {"robot.com.x|y|z", "the selected robot's true centre of mass [m]"},
      {"log.frames|mismatches|compared|replayed", "the loaded log and its last replay"},
  };
  return table;
}

std::vector<HelpEntry> help_entries() {
  std::vector<HelpEntry> entries;
  for (const auto& s : command_table())
    entries.push_back({std::string(s.name), std::string(s.usage) + " " + std::string(s.summary)});
  for (const auto& k : key_table())
    entries.push_back({std::string(k.pattern), std::string(k.summary)});
  return entries;
}

std::string help_text(const std::string& word) {
  const auto entries = help_entries();
  const std::size_t first_key = command_table().size();
  std::vector<std::size_t> shown;
  if (word.empty() || word == "keys") {
    for (std::size_t i = word.empty() ? 0 : first_key; i < entries.size(); ++i) shown.push_back(i);
  } else {
    shown = find_help(entries, word);
  }
  const std::string topic = help_topic_text(word);  // a topic's answer before the commands
  if (shown.empty()) return topic.empty() ? "no command or key matches '" + word + "'\n" : topic;
  return topic + help_listing(shown) + (word.empty() ? help_topic_list() : "");
}

std::string help_listing(const std::vector<std::size_t>& shown) {
  const std::size_t first_key = command_table().size();
  std::string out;
  bool keys_header = false;
  for (const std::size_t i : shown) {
    if (i < first_key) {
      const CommandSpec& s = command_table()[i];
      out += "  " + std::string(s.usage) + "\n      " + std::string(s.summary) + "\n";
      continue;
    }
    if (!keys_header) out += "keys:\n";
    keys_header = true;
    const KeySpec& k = key_table()[i - first_key];
    out += "  " + std::string(k.pattern) + "\n      " + std::string(k.summary) + "\n";
  }
  return out;
}

const CommandSpec* find_command(std::string_view name) {
  for (const auto& s : command_table())
    if (s.name == name) return &s;
  return nullptr;
}

std::vector<std::string> command_names() {
  std::vector<std::string> out;
  for (const auto& s : command_table()) out.emplace_back(s.name);
  return out;
}

}  // namespace stride::console
