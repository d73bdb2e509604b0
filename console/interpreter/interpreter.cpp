#include "console/interpreter/interpreter.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <new>
#include <ostream>
#include <sstream>
#include <thread>

#include "console/interpreter/console_plot.hpp"
#include "console/interpreter/tokenizer.hpp"
#include "console/interpreter/values.hpp"
#include "console/session/sim_session.hpp"
#include "console/view/view_bridge.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "robot/core/physical_limits.hpp"

namespace stride::console {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kMaxScriptDepth = 16;
}  // namespace

Interpreter::Interpreter(LocalTarget& local, std::ostream& out) : local_(local), out_(out) {}

Interpreter::~Interpreter() {
  try {
    finish();
  } catch (const Error& e) {
    out_ << "error: " << e.what() << "\n";
  }
}

void Interpreter::execute(std::string_view line) {
  const Command c = parse_command(line);
  try {
    dispatch(c);
  } catch (const debug::ConnectionLost& e) {
    lost_connection(e.what());
  } catch (const std::bad_alloc&) {  // a command asked for more than the machine has
    throw Error(c.name + ": out of memory");
  } catch (const std::filesystem::filesystem_error& e) {  // a path the system refuses
    throw Error(c.name + ": " + e.what());
  }
}

bool Interpreter::execute_reporting(std::string_view line) {
  try {
    execute(line);
    return true;
  } catch (const Error& e) {
    out_ << "error: " << e.what() << "\n";
    return false;
  }
}

void Interpreter::run_script(const std::string& path) {
  if (script_stack_.size() >= kMaxScriptDepth)
    throw Error("call: scripts nested deeper than " + std::to_string(kMaxScriptDepth));
  // A directory, device, FIFO or oversized file is refused before a byte is read.
  std::istringstream in(read_input_file(path, kMaxScriptBytes, "script"));
  script_stack_.push_back(path);
  std::string line;
  int number = 0;
  try {
    while (!quit_ && std::getline(in, line)) {
      ++number;
      try {
        execute(line);
      } catch (const Error& e) {
        rethrow_at(path, number, e);
      }
    }
  } catch (...) {
    script_stack_.pop_back();
    throw;
  }
  script_stack_.pop_back();
}

void Interpreter::run_inline(std::string_view commands) {
  int number = 0;
  for (const std::string& c : split_statements(commands)) {
    ++number;
    if (quit_) break;
    try {
      execute(c);
    } catch (const Error& e) {
      rethrow_at("-c", number, e);
    }
  }
}

std::string Interpreter::resolve(const std::string& path) const {
  if (fs::path(path).is_absolute() || script_stack_.empty()) return path;
  const fs::path beside = fs::path(script_stack_.back()).parent_path() / path;
  std::error_code ec;  // a name the system refuses (too long) is used as given, and fails there
  return fs::exists(beside, ec) ? beside.string() : path;
}

// Legal but absurd parameters of the local controllers (of `module`, or all) get a note line, as
// `stride run` gives them (behaviours/parameter_notes.hpp).
void Interpreter::note_parameters(const std::string& module) {
  SimSession& session = local_.session();
  for (int i = 0; i < session.simulation().robot_count(); ++i)
    if (const Runtime* rt = session.runtime(i))
      for (const std::string& n : parameter_notes(*rt))
        if (module.empty() || n.starts_with(module + ": ")) out_ << "note: " << n << "\n";
}

void Interpreter::load(const std::string& path) {
  simulation("load");
  const std::string resolved = find_input(resolve(path));  // a shipped scene from anywhere
  finish();
  local_.load(resolved);
  out_ << "loaded " << local_.name() << "\n";
  note_parameters("");
  const fs::path script = fs::path(resolved).replace_extension(".con");
  std::error_code ec;
  if (fs::exists(script, ec)) {
    out_ << "running " << script.string() << "\n";
    run_script(script.string());
  }
}

std::uint64_t Interpreter::steps_for(double seconds) const {
  // A robot whose loop starts with its first console has no period for a moment after connect.
  const double dt = remote_ ? remote_->refresh_period(2.0) : local_.step_seconds();
  if (!(dt > 0))
    throw Error(remote_ ? remote_->name() + " has no control period yet (its loop has not run)"
                        : "no scene loaded (use: load <scene.xml>)");
  if (const std::string p = limits::duration_problem(seconds); !p.empty())
    throw Error("seconds: " + p);
  return static_cast<std::uint64_t>(std::llround(seconds / dt));
}

void Interpreter::print_watches() {
  if (watch_keys_.empty() || ++steps_since_watch_ < watch_every_) return;
  steps_since_watch_ = 0;
  out_ << "t=" << target().time_text();
  for (const auto& k : watch_keys_) {
    std::string v;
    try {
      v = value(k);
    } catch (const Error& e) {
      v = "?";
    }
    out_ << "  " << k << "=" << v;
  }
  out_ << "\n";
}

void Interpreter::record_plot_row() {
  if (plot_keys_.empty()) return;
  std::vector<double> row{std::stod(target().time_text())};
  for (const auto& k : plot_keys_) {
    double v = std::nan("");
    try {
      const std::string text = value(k);
      v = text == "true" ? 1.0 : text == "false" ? 0.0 : parse_number(text, k);
    } catch (const Error&) {
    }
    row.push_back(v);
  }
  plot_table_.add_row(std::move(row));
  // A person watching a background run sees the plot grow: one line every few seconds.
  const auto now = std::chrono::steady_clock::now();
  if (running_ && now - plot_live_ > std::chrono::seconds(3)) {
    if (plot_live_ != std::chrono::steady_clock::time_point{})
      out_ << live_summary(plot_table_) << " (plot stop draws it)\n";
    plot_live_ = now;
  }
}

bool Interpreter::after_step() {
  if (step_hook_) step_hook_();
  print_watches();
  record_plot_row();
  RobotTarget& robot = target();
  DebugOutput debug = robot.take_debug_output();
  if (!debug.lines.empty()) {
    const std::string t = robot.time_text();
    for (const auto& line : debug.lines) out_ << "t=" << t << " " << line << "\n";
  }
  if (debug.stop.empty()) return true;
  out_ << "paused at t=" << robot.time_text() << ": " << debug.stop << "\n";
  return false;
}

void Interpreter::start_pacing() {
  pace_start_ = std::chrono::steady_clock::now();
  paced_steps_ = 0;
}

std::chrono::steady_clock::time_point Interpreter::step_due() {
  return pace_start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(paced_steps_ * target().step_seconds()));
}

void Interpreter::observe(const std::vector<std::string>& until_keys) {
  std::vector<std::string> observed = watch_keys_;
  observed.insert(observed.end(), plot_keys_.begin(), plot_keys_.end());
  observed.insert(observed.end(), until_keys.begin(), until_keys.end());
  observed.insert(observed.end(), observed_extra_.begin(), observed_extra_.end());
  target().observe(observed);
}

void Interpreter::report_dropped(std::uint64_t before) {
  RobotTarget& robot = target();
  if (const auto lost = robot.samples_dropped() - before; lost > 0)
    out_ << robot.name() << " dropped " << lost
         << " stream sample(s): this console read too slowly\n";
}

bool Interpreter::advance(std::uint64_t steps, const std::function<bool()>& until,
                          const std::vector<std::string>& until_keys) {
  RobotTarget& robot = target();
  if (!robot.loaded()) throw Error("no scene loaded (use: load <scene.xml>)");
  observe(until_keys);
  start_pacing();
  const std::uint64_t dropped_before = robot.samples_dropped();
  bool reached = false;
  robot.advance(steps, [&] {
    ++paced_steps_;
    if (!after_step()) return false;
    if (until && until()) return !(reached = true);
    if (interrupt_ && interrupt_->exchange(false)) {
      out_ << "paused at t=" << robot.time_text() << "\n";
      return false;
    }
    if (realtime_) std::this_thread::sleep_until(step_due());
    return true;
  });
  report_dropped(dropped_before);
  return reached;
}

std::chrono::steady_clock::duration Interpreter::run_slice(
    std::chrono::steady_clock::duration budget) {
  using Clock = std::chrono::steady_clock;
  poll_view();
  if (!running_) return Clock::duration::zero();
  const auto start = Clock::now();
  Clock::duration wait = Clock::duration::zero();
  struct FollowOn {  // a remote robot's stream outlives this slice while the run goes on
    Interpreter& in;
    explicit FollowOn(Interpreter& i) : in(i) {
      if (in.remote_) in.remote_->hold_stream(true);
    }
    ~FollowOn() {
      if (in.remote_ && !in.running_) in.remote_->hold_stream(false);
    }
  } follow{*this};
  try {
    RobotTarget& robot = target();
    observe({});
    const std::uint64_t dropped_before = robot.samples_dropped();
    const std::uint64_t done = robot.advance(run_steps_left_.value_or(UINT64_MAX), [&] {
      ++paced_steps_;
      if (!after_step()) return running_ = false;
      const auto now = Clock::now();
      if (realtime_ && step_due() > now) {
        wait = step_due() - now;  // the REPL reads input until the next step is due
        return false;
      }
      return now - start < budget;
    });
    report_dropped(dropped_before);
    if (run_steps_left_ && (*run_steps_left_ -= std::min(done, *run_steps_left_)) == 0)
      pause_run();  // run_for's time is up
  } catch (const debug::ConnectionLost& e) {
    running_ = false;
    lost_connection(e.what());
  } catch (...) {
    running_ = false;  // a failing step ends the run; the REPL reports the error
    throw;
  }
  return wait;
}

void Interpreter::restart() {
  pause_run();
  if (remote_) {
    remote_->restart();
    out_ << "restarted " << remote_->name() << "\n";
  } else {
    simulation("restart").reset();
    out_ << "reset " << local_.name() << "\n";
  }
  if (!interrupt_) return;  // a script goes on with its own `run`
  running_ = true;
  start_pacing();
  // A robot restarts between its frames, after the reply: its clock is not yet the new one.
  out_ << "running from " << (remote_ ? std::string("its start") : "t=" + target().time_text())
       << (realtime_ ? " in real time" : "") << " (pause or Ctrl-C stops)\n";
}

void Interpreter::pause_run() {
  if (!running_) return;
  running_ = false;
  if (remote_) remote_->hold_stream(false);
  run_steps_left_.reset();
  out_ << "paused at t=" << target().time_text() << "\n";
}

void Interpreter::run_for(double seconds) {
  refuse_while_running("run");
  const std::uint64_t steps = steps_for(seconds);
  start_background_run();
  run_steps_left_ = steps;
}

void Interpreter::start_background_run() {
  if (!target().loaded()) throw Error("no scene loaded (use: load <scene.xml>)");
  running_ = true;
  run_steps_left_.reset();
  start_pacing();
}

void Interpreter::refuse_while_running(const std::string& command) const {
  if (running_)
    throw Error(command + ": the simulation is running in the background (pause first)");
}

void Interpreter::run(const std::vector<std::string>& a) {
  if (!a.empty()) return void(advance(steps_for(parse_number(a[0], "seconds")), nullptr));
  if (!interrupt_) throw Error("run: give the seconds to run in a script");
  start_background_run();
  out_ << "running from t=" << target().time_text()
       << (realtime_ ? " in real time (realtime off: as fast as possible;"
                     : " as fast as possible (realtime on: at the wall clock's pace;")
       << " commands apply between frames; pause or Ctrl-C stops)\n";
}

void Interpreter::set(const std::vector<std::string>& a) {
  std::string fields;
  for (std::size_t i = 1; i < a.size(); ++i) fields += (i > 1 ? " " : "") + a[i];
  target().set(a[0], fields);
  if (!remote_ && a[0].starts_with("module:")) {
    const std::string module = a[0].substr(7);
    note_parameters(module.substr(0, module.find('.')));
  }
}

void Interpreter::move_robot(const std::vector<std::string>& a) {
  simulation("mv").move_robot(parse_number(a[0], "x"), parse_number(a[1], "y"),
                              parse_number(a[2], "z"),
                              a.size() > 3 ? parse_number(a[3], "yaw")
                                           : parse_number(local_.get("robot.torso.yaw"), "yaw"));
}

void Interpreter::dispatch(const Command& c) {
  const auto& a = c.args;
  const std::string& n = c.name;
  if (n.empty()) return;
  if (n == "help") return help(a);
  if (n == "load" || n == "reset") pause_run();  // a new world starts paused
  if (n == "load") return load(a[0]);
  if (n == "reset") {
    simulation(n).reset();
    out_ << "reset " << local_.name() << "\n";
    return;
  }
  if (n == "restart") return restart();
  if (n == "run" || n == "step" || n == "wait") refuse_while_running(n);
  if (n == "run") return run(a);
  if (n == "step") {
    simulation(n);
    advance(
        a.empty() ? 1 : static_cast<std::uint64_t>(parse_integer(a[0], "frames", 1, 1000000000)),
        nullptr);
    return;
  }
  if (n == "pause") {
    if (running_) return pause_run();
    out_ << "paused at t=" << target().time_text() << "\n";
    return;
  }
  if (n == "realtime") {
    realtime_ = parse_on_off(a[0], "realtime");
    start_pacing();  // a background run keeps the wall clock from now on
    return;
  }
  if (n == "get") return get(a);
  if (n == "set") return set(a);
  if (n == "mr") return module_request(a);
  if (n == "dr") return debug_request(a);
  if (n == "watch") return watch(a);
  if (n == "plot") return plot(a);
  if (n == "log") return log(a);
  if (n == "report") return report(a);
  if (n == "push") {
    simulation(n).push(a[0], parse_number(a[1], "fx"), parse_number(a[2], "fy"),
                       parse_number(a[3], "fz"), parse_number(a[4], "seconds"));
    return;
  }
  // The background run belongs to the target it was started on.
  if (n == "connect" || n == "disconnect") pause_run();
  if (n == "robot") return robot_command(c);
  if (n == "connect") return connect(a);
  if (n == "disconnect") return disconnect(a);
  if (n == "serve") return serve(a);
  if (n == "view") return view(a);
  if (n == "mv") return move_robot(a);
  if (n == "sn") return simulation(n).sensor_switch(a[0], parse_on_off(a[1], a[0]));
  if (n == "snapshot") {
    simulation(n).snapshot(a[0], a.size() > 1 ? a[1] : "");
    out_ << "wrote " << a[0] << "\n";
    return;
  }
  if (n == "video") return video(a);
  if (n == "expect") return expect(a);
  if (n == "wait") return wait_until(a);
  if (n == "call") return run_script(resolve(a[0]));
  if (n == "sweep") return sweep_.run(a, resolve(a[0]), out_, interrupt_ != nullptr);
  if (n == "tune") return tune_.run(a, resolve(a[0]), out_, interrupt_ != nullptr);
  if (n == "echo") {
    for (std::size_t i = 0; i < a.size(); ++i) out_ << (i ? " " : "") << a[i];
    out_ << "\n";
    return;
  }
  if (n == "quit") {
    quit_ = true;
    return;
  }
  throw Error(n + ": not implemented");  // the table and this dispatch must list the same names
}

}  // namespace stride::console
