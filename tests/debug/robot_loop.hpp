#pragma once
// A robot's loop for the debug-server tests: a Runtime on the FakeLink (test modules + Stand)
// stepped by its own thread at a fixed real-time period, with a DebugServer at its frame
// boundary. Records how many frames ran, how many finished late, and the longest time the
// boundary (the loop's whole exchange with the server) took.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "robot/debug/server.hpp"
#include "tests/framework/fake_link.hpp"
#include "timed_boundary.hpp"

namespace stride::test {

class RobotLoop {
 public:
  explicit RobotLoop(debug::ServerOptions options, double period = 0.01,
                     ModuleRegistry registry = test_registry(),
                     RuntimeConfig config = test_config())
      : registry_(std::move(registry)),
        link_(period),
        runtime_(registry_, config, link_),
        server_(with_log(std::move(options))),
        timed_(server_.boundary()),
        period_(period) {
    runtime_.set_frame_boundary(&timed_);
    thread_ = std::thread([this] { run(); });
  }
  ~RobotLoop() { stop(); }

  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
    runtime_.set_frame_boundary(nullptr);
  }
  const debug::Endpoint& endpoint() const { return server_.endpoint(); }
  debug::DebugServer& server() { return server_; }
  Runtime& runtime() { return runtime_; }  // only once stopped
  std::int64_t frames() const { return frames_; }
  std::int64_t late_frames() const { return late_; }
  double longest_boundary_seconds() const { return timed_.longest_ns.load() * 1e-9; }
  std::vector<std::string> log_lines() {
    std::lock_guard<std::mutex> lock(log_mutex_);
    return log_;
  }
  std::size_t log_count(const std::string& part) {
    const auto lines = log_lines();
    return static_cast<std::size_t>(std::count_if(lines.begin(), lines.end(), [&](const auto& l) {
      return l.find(part) != std::string::npos;
    }));
  }

 private:
  debug::ServerOptions with_log(debug::ServerOptions o) {
    o.log = [this](const std::string& line) {
      std::lock_guard<std::mutex> lock(log_mutex_);
      log_.push_back(line);
    };
    return o;
  }
  void run() {
    using Clock = std::chrono::steady_clock;
    const auto period =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(period_));
    auto due = Clock::now();
    while (!stop_) {
      runtime_.step();
      ++frames_;
      due += period;
      if (Clock::now() > due) ++late_;
      std::this_thread::sleep_until(due);
    }
  }

  ModuleRegistry registry_;
  FakeLink link_;
  Runtime runtime_;
  std::mutex log_mutex_;
  std::vector<std::string> log_;
  debug::DebugServer server_;
  TimedBoundary timed_;
  double period_;
  std::atomic<bool> stop_{false};
  std::atomic<std::int64_t> frames_{0}, late_{0};
  std::thread thread_;
};

inline debug::ServerOptions loopback_options() {
  debug::ServerOptions o;
  o.listen = {"127.0.0.1", 0};
  o.robot = "testbot";
  return o;
}

}  // namespace stride::test
