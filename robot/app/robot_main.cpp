#include "robot/app/robot_main.hpp"

#include <algorithm>
#include <ostream>
#include <vector>

#include "robot/app/flags.hpp"
#include "robot/app/robot_process.hpp"
#include "robot/app/stop_signals.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/one_line.hpp"
#include "robot/core/thread_priority.hpp"
#include "robot/debug/server.hpp"

namespace stride {
namespace {

// A console connecting a moment late must not miss the walk: the robot stands, its LoLA frames
// answered with no command, and the controller starts with the first console. False: the link
// was lost for good.
bool wait_for_console(RobotProcess& robot, debug::DebugServer& server, StopSignals& stop,
                      std::ostream& err) {
  err << "stride robot: standing, controller paused until the first console connects "
         "(--no-wait starts at once)"
      << std::endl;
  const bool held = robot.hold_until(
      [&](Runtime& rt) {
        server.idle(rt);
        return server.stats().clients > 0;
      },
      [&] { return stop.requested(); });
  if (held) err << "stride robot: a console connected: controller running" << std::endl;
  return held || stop.requested();
}

}  // namespace

int robot_main(std::span<const std::string> args, const ModuleRegistry& registry, std::ostream& out,
               std::ostream& err) {
  StopSignals stop;  // from here on SIGINT/SIGTERM end the run between frames
  std::unique_ptr<RobotProcess> robot;
  std::unique_ptr<debug::DebugServer> server;
  bool no_wait = false;
  try {
    // --no-wait (no value): with --debug, the controller starts at once instead of holding the
    // robot as it stands until the first console connects.
    std::vector<std::string> words(args.begin(), args.end());
    const auto no_wait_at = std::find(words.begin(), words.end(), "--no-wait");
    no_wait = no_wait_at != words.end();
    if (no_wait) words.erase(no_wait_at);
    const Flags f = read_flags(words,
                               {"--config", "--lola", "--log", "--debug", "--token-file",
                                "--log-dir", "--rt-priority", "--cpu"},
                               "stride robot");
    if (!f.positional.empty())
      throw Error("stride robot: unexpected argument '" + f.positional[0] + "'");
    const std::string rt_text = f.value_or("--rt-priority", "");
    const int rt_priority =
        rt_text.empty() ? 0 : parse_realtime_priority(rt_text, "stride robot: --rt-priority");
    const std::string cpu_text = f.value_or("--cpu", "");
    const int cpu = cpu_text.empty()
                        ? -1
                        : static_cast<int>(parse_integer(cpu_text, "stride robot: --cpu", 0, 1023));
    const std::string config_path = f.value_or("--config", "");
    if (config_path.empty()) throw Error("stride robot: --config <robot.xml> is required");
    RobotConfig config = parse_robot_config_file(config_path);
    config.lola_socket = f.value_or("--lola", config.lola_socket);
    const std::string name = config.name;
    robot = std::make_unique<RobotProcess>(std::move(config), registry, err);
    const std::string log = f.value_or("--log", "");
    if (!log.empty()) robot->start_log(log);
    if (const std::string at = f.value_or("--debug", ""); !at.empty()) {
      debug::ServerOptions options;
      options.listen = debug::parse_endpoint(at, "stride robot: --debug");
      options.tokens = debug::tokens_from(f.value_or("--token-file", ""));
      options.log_dir = f.value_or("--log-dir", ".");
      options.robot = name;
      server = std::make_unique<debug::DebugServer>(std::move(options));
      server->allow_restart();  // `restart` rebuilds the controller from its configuration
      robot->set_frame_boundary(&server->boundary());
      err << "stride robot: debug server on " << server->endpoint().text() << std::endl;
    } else if (no_wait) {
      throw Error("stride robot: --no-wait goes with --debug <addr:port>");
    }
    // Last, as nothing started here should share the loop's CPU or level.
    if (cpu >= 0) set_cpu_affinity({cpu}, "stride robot: --cpu");
    if (rt_priority > 0) set_realtime_priority(rt_priority, "stride robot: --rt-priority");
  } catch (const Error& e) {
    err << e.what() << std::endl;
    return kRobotBadInput;
  }
  int code = kRobotModuleFailed;
  try {
    const bool waited = !server || no_wait || wait_for_console(*robot, *server, stop, err);
    if (!waited)
      code = kRobotLinkLost;
    else if (stop.requested())
      code = kRobotStopped;
    else
      code = robot->run([&] { return stop.requested(); },
                        [&] { return server && server->take_restart(); });
  } catch (
      const std::exception& e) {  // whatever escaped the loop: one line and the summary, no abort
    err << "stride robot: the control loop stopped: " << one_line(e.what(), 200) << std::endl;
  }
  if (stop.signal() != 0)
    err << "stride robot: " << (stop.signal() == SIGINT ? "SIGINT" : "SIGTERM")
        << ": stopped after a complete frame" << std::endl;
  out << robot->summary() << std::flush;
  if (server) robot->set_frame_boundary(nullptr);
  server.reset();
  robot.reset();  // closes the log and the socket
  return code;
}

}  // namespace stride
