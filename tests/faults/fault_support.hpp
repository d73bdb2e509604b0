#pragma once
// What the fault-injection tests share: the robot started on a fake LoLA, numbers read out of its
// summary, and one line per fault of what it cost (frames missed), printed for the README table.
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "tests/faults/fake_lola.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride::test {

// The number after `label` in `text` (e.g. "frames " in the robot's summary), or -1.
inline long number_after(const std::string& text, const std::string& label) {
  const auto at = text.find(label);
  if (at == std::string::npos) return -1;
  return std::stol(text.substr(at + label.size()));
}

// A robot config for the Stand controller with `safety` attributes, named after the test.
inline std::string stand_config(const std::string& name, const std::string& safety) {
  return robot_config(name, kStandController, safety);
}

// `stride-robot` (the Stand controller) started on a fake LoLA at <scratch>/<name>.sock and
// accepted by it; `file_size_limit` > 0 puts it on a "full disk".
struct RobotOnFakeLola {
  FakeLola lola;
  std::optional<ChildProcess> robot;
  bool connected = false;

  RobotOnFakeLola(const std::string& name, const std::string& safety,
                  std::vector<std::string> extra = {}, std::uint64_t file_size_limit = 0)
      : lola(ChildProcess::scratch(name + ".sock")) {
    std::vector<std::string> argv = {kStrideRobot, "--config", stand_config(name, safety), "--lola",
                                     ChildProcess::scratch(name + ".sock")};
    argv.insert(argv.end(), extra.begin(), extra.end());
    if (file_size_limit > 0)
      robot.emplace(argv, name + "_robot", file_size_limit);
    else
      robot.emplace(argv, name + "_robot");
    connected = lola.accept(60);
  }
  // SIGTERM between frames; its exit code (nothing if it did not end within 10 s).
  std::optional<int> stop() {
    robot->signal(SIGTERM);
    return robot->wait_for(10);
  }
};

// "fault: <what> | frames missed <n> of <m> | <outcome>": one row of robot/hal/README.md's table.
inline void print_fault_row(const std::string& fault, int missed, int frames,
                            const std::string& outcome) {
  std::printf("[fault] %s | frames missed %d of %d | %s\n", fault.c_str(), missed, frames,
              outcome.c_str());
  std::fflush(stdout);
}

// The endpoint after "debug server on " in a robot's stderr, waited for (bounded).
inline std::string debug_endpoint(const ChildProcess& robot, double seconds) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < give_up) {
    const std::string err = robot.err();
    const auto at = err.find("debug server on ");
    if (at != std::string::npos && err.find('\n', at) != std::string::npos)
      return err.substr(at + 16, err.find('\n', at) - at - 16);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return "";
}

}  // namespace stride::test
