#include "console/sweep/lola_robot.hpp"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "robot/app/robot_config_text.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"

namespace stride::sweep {
namespace {

namespace fs = std::filesystem;

std::string private_dir() {
  std::string pattern = (fs::temp_directory_path() / "stride-lola-XXXXXX").string();
  if (!::mkdtemp(pattern.data()))
    throw Error("sweep --through-lola: cannot create a folder in " +
                fs::temp_directory_path().string());
  return pattern;
}

// The log's last non-empty line: what a robot process said before it ended.
std::string last_line(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last.empty() ? "(it wrote nothing)" : last;
}

}  // namespace

LolaRobot::LolaRobot(RobotConfig config, const sim::SimulatedRobot& robot) : dir_(private_dir()) {
  try {
    config.lola_socket = dir_ + "/lola";
    config.period = robot.period();
    config.connect_timeout = kConnectTimeout;
    config.link_timeout = sim::kLockstepAnswerTimeout;  // this side may be slow, not gone
    write_file(dir_ + "/robot.xml", robot_config_xml(config));
    server_ = std::make_unique<sim::LolaServer>(config.lola_socket, sim::LolaPacing::Lockstep,
                                                robot, events_);
    const std::string exe = console::sibling_executable("stride-robot");
    if (!fs::exists(exe))
      throw Error("sweep --through-lola: " + exe +
                  " does not exist (build the stride-robot target)");
    child_ = std::make_unique<console::RunningChild>(
        std::vector<std::string>{exe, "--config", dir_ + "/robot.xml"}, dir_ + "/robot.log");
    wait_for_connection();
  } catch (...) {
    child_.reset();
    server_.reset();
    std::error_code ec;
    fs::remove_all(dir_, ec);
    throw;
  }
}

LolaRobot::~LolaRobot() {
  child_.reset();   // ends the robot process first: it holds the socket's other end
  server_.reset();  // closes and removes the socket
  std::error_code ec;
  fs::remove_all(dir_, ec);
}

std::string LolaRobot::failure(const std::string& what) {
  const std::string pid = child_ ? std::to_string(child_->pid()) : "-";
  std::string how = child_ ? (child_->ended() ? child_->how_it_ended() : "still running") : "";
  return "stride-robot (pid " + pid + ", " + dir_ + "/lola): " + what + " (" + how +
         "; its last line: " + last_line(dir_ + "/robot.log") + ")";
}

void LolaRobot::wait_for_connection() {
  const auto until =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(kConnectTimeout);
  for (;;) {
    try {
      server_->wait_for_client(0.2);
      return;
    } catch (const Error&) {
      // not yet: is it still starting?
    }
    if (child_->ended()) throw Error(failure("ended before it connected"));
    if (std::chrono::steady_clock::now() >= until)
      throw Error(failure("did not connect within " +
                          std::to_string(static_cast<int>(kConnectTimeout)) + " s"));
  }
}

bool LolaRobot::control_frame(const hal::SensorFrame& sensors, hal::ActuatorFrame& commands) {
  const bool answered = server_->control_frame(sensors, commands);
  const sim::LolaServeReport& r = server_->report();
  if (r.clients_lost > 0 || r.bad_packets > 0)
    throw Error(failure(r.bad_packets > 0 ? "sent a packet that did not decode at " +
                                                std::to_string(sensors.time) + " s"
                        : r.events.empty() ? "lost"
                                           : r.events.back()));
  return answered;
}

void LolaRobot::finish() {
  const sim::LolaServeReport& r = server_->report();
  if (r.exchanged != r.frames)
    throw Error(failure(std::to_string(r.frames - r.exchanged) + " of " + std::to_string(r.frames) +
                        " frames without an answer"));
  child_->stop();
}

}  // namespace stride::sweep
