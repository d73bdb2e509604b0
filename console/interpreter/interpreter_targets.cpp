// The commands of Interpreter that choose what the console acts on: robot, connect, disconnect,
// serve; and the routing of robot-side and simulation-only commands.
#include <cstdlib>
#include <ostream>

#include "console/interpreter/interpreter.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

RobotTarget& Interpreter::target() {
  if (remote_) return *remote_;
  return local_;
}

SimulationTarget& Interpreter::simulation(const std::string& command) {
  if (remote_)
    throw Error("'" + command + "' acts on a simulation; the console is on " + remote_->name() +
                " (disconnect, or robot <name>, goes back to the local simulation)");
  return local_;
}

std::string Interpreter::value(const std::string& key) {
  if (key.starts_with("sweep.")) return sweep_.value(key);  // the last sweep run here
  if (key.starts_with("tune.")) return tune_.value(key);    // the last search run here
  if (key.starts_with("log.")) return local_.get(key);      // the console's log player
  return target().get(key);
}

std::vector<std::string> Interpreter::robot_names() {
  std::vector<std::string> names;
  if (local_.loaded()) names = local_.robot_names();
  for (const auto& [label, remote] : remotes_) names.push_back(label);
  return names;
}

void Interpreter::robot_command(const Command& c) {
  const auto& a = c.args;
  if (a.empty() || a[0] == "?") {
    const bool local_current = remote_ == nullptr;
    if (local_.loaded() || remotes_.empty()) {
      const std::string selected = local_.selected_robot();  // throws without a scene
      for (const auto& name : local_.robot_names())
        out_ << (local_current && name == selected ? "* " : "  ") << name << "\n";
    }
    for (const auto& [label, remote] : remotes_)
      out_ << (remote.get() == remote_ ? "* " : "  ") << label << " (" << remote->name()
           << ", remote)\n";
    return;
  }
  for (const auto& [label, remote] : remotes_) {
    if (label != a[0] && remote->robot() != a[0]) continue;
    if (remote_ != remote.get()) pause_run();  // the background run belongs to its target
    remote_ = remote.get();
    out_ << "commands act on " << remote_->name() << "\n";
    return;
  }
  if (remote_) pause_run();
  local_.select_robot(a[0]);
  remote_ = nullptr;
}

void Interpreter::connect(const std::vector<std::string>& a) {
  const debug::Endpoint endpoint = debug::parse_endpoint(a[0], "connect");
  const char* env = std::getenv("STRIDE_TOKEN");
  const std::string token = a.size() > 1 ? a[1] : env ? env : "";
  auto remote = std::make_unique<RemoteTarget>(endpoint, token);
  if (auto it = remotes_.find(remote->label()); it != remotes_.end()) {
    if (log_target_ == it->second.get()) log_target_ = nullptr;
    remotes_.erase(it);  // a second connect to the same robot replaces the first
  }
  remote_ = remote.get();
  remotes_.emplace(remote->label(), std::move(remote));
  // A robot that waited for this console starts its loop now: its period comes a frame later.
  out_ << "connected to " << remote_->name() << " (period " << remote_->refresh_period(1.0) << " s"
       << (remote_->read_only() ? ", read-only" : "") << ")\n";
}

void Interpreter::disconnect(const std::vector<std::string>& a) {
  auto it = remotes_.end();
  if (!a.empty()) {
    it = remotes_.find(a[0]);
    if (it == remotes_.end()) throw Error("not connected to '" + a[0] + "'");
  } else {
    if (!remote_) throw Error("the console is not on a remote robot");
    it = remotes_.find(remote_->label());
  }
  const std::string name = it->second->name();
  if (log_target_ == it->second.get()) log_target_ = nullptr;
  if (remote_ == it->second.get()) remote_ = nullptr;
  remotes_.erase(it);
  out_ << "disconnected from " << name << "; commands act on " << target().name() << "\n";
}

void Interpreter::lost_connection(const std::string& why) {
  const std::string gone = remote_ ? remote_->label() : "";
  if (log_target_ && log_target_ == remote_) log_target_ = nullptr;
  remotes_.erase(gone);
  remote_ = nullptr;
  throw Error(why + " (back on " + local_.name() + "; connect again to resume)");
}

void Interpreter::serve(const std::vector<std::string>& a) {
  if (a[0] == "stop") {
    if (!local_.serving()) throw Error("serve stop: not serving");
    local_.stop_serving();
    out_ << "stopped serving\n";
    return;
  }
  debug::ServerOptions options;
  options.listen = debug::parse_endpoint(a[0], "serve");
  options.tokens = debug::tokens_from(a.size() > 1 ? a[1] : "");
  const debug::Endpoint at = local_.serve(std::move(options));
  out_ << "serving robot " << local_.selected_robot() << " on " << at.text()
       << " (another console: connect " << at.text() << ")\n";
}

void Interpreter::idle() {
  for (auto it = remotes_.begin(); it != remotes_.end();) {
    try {
      // Said at once, above the prompt: a person waiting there must not miss a fall.
      const std::string who = it->second.get() == remote_ ? "" : "[" + it->first + "] ";
      for (const auto& line : it->second->idle_lines()) out_ << who << line << "\n";
      ++it;
    } catch (const debug::ConnectionLost& e) {
      out_ << "error: " << e.what() << "\n";
      if (log_target_ == it->second.get()) log_target_ = nullptr;
      if (remote_ == it->second.get()) remote_ = nullptr;
      it = remotes_.erase(it);
    }
  }
  local_.serve_idle();
  poll_view();
}

}  // namespace stride::console
