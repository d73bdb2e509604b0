#include "console/interpreter/interpreter.hpp"

#include <cmath>
#include <filesystem>
#include <new>
#include <ostream>
#include <sstream>
#include <thread>

#include "console/interpreter/tokenizer.hpp"
#include "console/interpreter/values.hpp"
#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "robot/model/physical_limits.hpp"

namespace stride::console {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kMaxScriptDepth = 16;
}  // namespace

Interpreter::Interpreter(Target& target, std::ostream& out) : target_(target), out_(out) {}

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
  } catch (const std::bad_alloc&) {  // a command asked for more than the machine has
    throw Error(c.name + ": out of memory");
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
        throw error_at(path, number, e.what());
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
      throw error_at("-c", number, e.what());
    }
  }
}

std::string Interpreter::resolve(const std::string& path) const {
  if (fs::path(path).is_absolute() || script_stack_.empty()) return path;
  const fs::path beside = fs::path(script_stack_.back()).parent_path() / path;
  return fs::exists(beside) ? beside.string() : path;
}

void Interpreter::load(const std::string& path) {
  const std::string resolved = resolve(path);
  finish();
  target_.load(resolved);
  out_ << "loaded " << target_.name() << "\n";
  const fs::path script = fs::path(resolved).replace_extension(".con");
  if (fs::exists(script)) {
    out_ << "running " << script.string() << "\n";
    run_script(script.string());
  }
}

std::uint64_t Interpreter::steps_for(double seconds) const {
  const double dt = target_.step_seconds();
  if (!(dt > 0)) throw Error("no scene loaded (use: load <scene.xml>)");
  if (const std::string p = limits::duration_problem(seconds); !p.empty())
    throw Error("seconds: " + p);
  return static_cast<std::uint64_t>(std::llround(seconds / dt));
}

void Interpreter::after_step() {
  if (!watch_keys_.empty() && ++steps_since_watch_ >= watch_every_) {
    steps_since_watch_ = 0;
    out_ << "t=" << target_.get("sim.time");
    for (const auto& k : watch_keys_) {
      std::string v;
      try {
        v = target_.get(k);
      } catch (const Error& e) {
        v = "?";
      }
      out_ << "  " << k << "=" << v;
    }
    out_ << "\n";
  }
  if (!plot_keys_.empty()) {
    std::vector<double> row{std::stod(target_.get("sim.time"))};
    for (const auto& k : plot_keys_) {
      double v = std::nan("");
      try {
        const std::string text = target_.get(k);
        v = text == "true" ? 1.0 : text == "false" ? 0.0 : parse_number(text, k);
      } catch (const Error&) {
      }
      row.push_back(v);
    }
    plot_table_.add_row(std::move(row));
  }
}

bool Interpreter::advance(std::uint64_t steps, const std::function<bool()>& until) {
  if (!target_.loaded()) throw Error("no scene loaded (use: load <scene.xml>)");
  run_wall_start_ = std::chrono::steady_clock::now();
  run_sim_start_ = std::stod(target_.get("sim.time"));
  const double dt = target_.step_seconds();
  std::uint64_t done = 0;
  bool reached = false;
  target_.advance(steps, [&] {
    ++done;
    after_step();
    if (until && until()) return !(reached = true);
    if (interrupt_ && interrupt_->exchange(false)) {
      out_ << "paused at t=" << target_.get("sim.time") << "\n";
      return false;
    }
    if (realtime_) {
      const auto due =
          run_wall_start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                std::chrono::duration<double>(done * dt));
      if (due > std::chrono::steady_clock::now()) std::this_thread::sleep_until(due);
    }
    return true;
  });
  return reached;
}

void Interpreter::dispatch(const Command& c) {
  const auto& a = c.args;
  const std::string& n = c.name;
  if (n.empty()) return;
  if (n == "help") return help(a);
  if (n == "load") return load(a[0]);
  if (n == "reset") {
    target_.reset();
    out_ << "reset " << target_.name() << "\n";
    return;
  }
  if (n == "run") {
    if (a.empty() && !interrupt_) throw Error("run: give the seconds to run in a script");
    const std::uint64_t steps =
        a.empty() ? std::uint64_t(-1) : steps_for(parse_number(a[0], "seconds"));
    advance(steps, nullptr);
    return;
  }
  if (n == "step") {
    advance(
        a.empty() ? 1 : static_cast<std::uint64_t>(parse_integer(a[0], "frames", 1, 1000000000)),
        nullptr);
    return;
  }
  if (n == "pause") {
    out_ << "paused at t=" << target_.get("sim.time") << "\n";
    return;
  }
  if (n == "realtime") {
    realtime_ = parse_on_off(a[0], "realtime");
    return;
  }
  if (n == "get") return get(a);
  if (n == "set") {
    std::string fields;
    for (std::size_t i = 1; i < a.size(); ++i) fields += (i > 1 ? " " : "") + a[i];
    target_.set(a[0], fields);
    return;
  }
  if (n == "mr") return module_request(a);
  if (n == "dr") return debug_request(a);
  if (n == "watch") return watch(a);
  if (n == "plot") return plot(a);
  if (n == "log") return log(a);
  if (n == "report") return report(a);
  if (n == "push") {
    target_.push(a[0], parse_number(a[1], "fx"), parse_number(a[2], "fy"), parse_number(a[3], "fz"),
                 parse_number(a[4], "seconds"));
    return;
  }
  if (n == "robot") return select_robot(a);
  if (n == "mv") {
    target_.move_robot(parse_number(a[0], "x"), parse_number(a[1], "y"), parse_number(a[2], "z"),
                       a.size() > 3 ? parse_number(a[3], "yaw")
                                    : parse_number(target_.get("robot.torso.yaw"), "yaw"));
    return;
  }
  if (n == "sn") return target_.sensor_switch(a[0], parse_on_off(a[1], a[0]));
  if (n == "snapshot") {
    target_.snapshot(a[0], a.size() > 1 ? a[1] : "");
    out_ << "wrote " << a[0] << "\n";
    return;
  }
  if (n == "video") return video(a);
  if (n == "expect") return expect(a);
  if (n == "wait") return wait_until(a);
  if (n == "call") return run_script(resolve(a[0]));
  if (n == "sweep") return sweep_.run(a, resolve(a[0]), out_, interrupt_ != nullptr);
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
