#include "console/repl/completion.hpp"

#include <algorithm>
#include <filesystem>

#include "console/interpreter/command_table.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> starting_with(const std::vector<std::string>& all, const std::string& p) {
  std::vector<std::string> out;
  for (const auto& s : all)
    if (s.starts_with(p)) out.push_back(s);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Names from the target; an unloaded or remote-less target simply offers nothing.
template <class F>
auto safely(F f) -> decltype(f()) {
  try {
    return f();
  } catch (const Error&) {
    return {};
  }
}

const std::vector<std::string> kSimKeys = {
    "sim.time",        "sim.steps",     "sim.hash",      "robot.name",       "robot.fell",
    "robot.torso.x",   "robot.torso.y", "robot.torso.z", "robot.torso.roll", "robot.torso.pitch",
    "robot.torso.yaw", "robot.com.x",   "robot.com.y",   "robot.com.z",      "log.frames",
    "log.complete",    "log.damaged",   "log.truncated", "log.mismatches",   "log.compared",
    "log.replayed"};

std::vector<std::string> field_names(const std::string& key, RobotTarget& target) {
  return safely([&] {
    const TypeDesc& d = target.type_of(key);
    std::vector<std::string> out;
    for (const auto& f : d.fields) out.push_back(f.name);
    if (d.vector_components) {
      const char* xyzw[] = {"x", "y", "z", "w"};
      for (std::size_t i = 0; i < d.length && i < 4; ++i) out.push_back(xyzw[i]);
    }
    return out;
  });
}

}  // namespace

std::vector<std::string> complete_path(const std::string& word) {
  const auto slash = word.rfind('/');
  const std::string dir = slash == std::string::npos ? "" : word.substr(0, slash + 1);
  const std::string stem = slash == std::string::npos ? word : word.substr(slash + 1);
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir.empty() ? "." : dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!name.starts_with(stem) || (stem.empty() && name.starts_with("."))) continue;
    out.push_back(dir + name + (e.is_directory(ec) ? "/" : ""));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> complete_key(const std::string& word, RobotTarget& target) {
  const auto colon = word.find(':');
  if (colon == std::string::npos) {
    std::vector<std::string> all = {"representation:", "module:"};
    all.insert(all.end(), kSimKeys.begin(), kSimKeys.end());
    return starting_with(all, word);
  }
  const std::string prefix = word.substr(0, colon + 1);
  const auto dot = word.rfind('.');
  if (dot == std::string::npos || dot < colon) {
    const auto names = prefix == "module:" ? safely([&] { return target.parameter_modules(); })
                                           : safely([&] { return target.representations(); });
    std::vector<std::string> keys;
    for (const auto& n : names) keys.push_back(prefix + n);
    return starting_with(keys, word);
  }
  const std::string parent = word.substr(0, dot);
  std::vector<std::string> keys;
  for (const auto& f : field_names(parent, target)) keys.push_back(parent + "." + f);
  return starting_with(keys, word);
}

std::vector<std::string> complete(const std::vector<std::string>& before, const std::string& word,
                                  RobotTarget& target, const std::vector<std::string>& robots) {
  if (before.empty()) return starting_with(command_names(), word);
  const std::string& command = before[0];
  const std::size_t position = before.size();  // index of `word` among the arguments + 1
  if (command == "load" || command == "call" || command == "report") return complete_path(word);
  if (command == "get" || command == "watch" || command == "plot" || command == "expect") {
    if (command == "expect" && position == 2)
      return starting_with({"==", "!=", "<", "<=", ">", ">=", "~="}, word);
    if (command == "get" && position == 2) return starting_with({"?"}, word);
    if (position == 1 || command == "watch" || command == "plot") return complete_key(word, target);
    return {};
  }
  if (command == "set") {
    if (position == 1) return complete_key(word, target);
    std::vector<std::string> fields;
    for (const auto& f : field_names(before[1], target)) fields.push_back(f + "=");
    return starting_with(fields, word);
  }
  if (command == "wait") {
    if (position == 1) return starting_with({"until"}, word);
    if (position == 2) return complete_key(word, target);
    if (position == 3) return starting_with({"==", "!=", "<", "<=", ">", ">=", "~="}, word);
    if (position == 5) return starting_with({"timeout"}, word);
    return {};
  }
  if (command == "mr") {
    if (position == 1) {
      auto reps = safely([&] { return target.representations(); });
      reps.push_back("?");
      return starting_with(reps, word);
    }
    if (position == 2) {
      auto modules = safely([&] { return target.providers_available(before[1]); });
      modules.push_back("default");
      modules.push_back("?");
      return starting_with(modules, word);
    }
    return {};
  }
  if (command == "dr") {
    if (position == 1) {
      std::vector<std::string> names{"?"};
      for (const auto& [n, state] : safely([&] { return target.debug_requests(); }))
        names.push_back(n);
      return starting_with(names, word);
    }
    return position == 2 ? starting_with({"on", "off", "quiet"}, word) : std::vector<std::string>{};
  }
  if (command == "sn") {
    if (position == 1) return starting_with({"noise", "delay", "quantise"}, word);
    return position == 2 ? starting_with({"on", "off"}, word) : std::vector<std::string>{};
  }
  if (command == "realtime" && position == 1) return starting_with({"on", "off"}, word);
  if (command == "robot" && position == 1) {
    auto names = robots;
    names.push_back("?");
    return starting_with(names, word);
  }
  if (command == "log") {
    if (position == 1)
      return starting_with({"start", "stop", "save", "load", "info", "goto", "export", "replay"},
                           word);
    if (before[1] == "export" && position >= 3) {
      // Log export keys name representations without the prefix: JointRequest.position[3].
      std::vector<std::string> keys;
      for (const auto& k : complete_key("representation:" + word, target))
        keys.push_back(k.substr(std::string("representation:").size()));
      return keys;
    }
    return complete_path(word);
  }
  if (command == "help" && position == 1) return starting_with(command_names(), word);
  return {};
}

}  // namespace stride::console
