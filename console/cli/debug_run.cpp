#include "console/cli/debug_run.hpp"

#include <chrono>
#include <ostream>
#include <thread>

#include "robot/app/stop_signals.hpp"
#include "robot/core/error.hpp"
#include "robot/debug/server.hpp"

namespace stride::cli {

double serve_simulation(console::SimSession& session, const DebugRun& run, std::ostream& out) {
  auto& sim = session.simulation();
  Runtime* rt = sim.robot_count() > 0 ? session.runtime(0) : nullptr;
  if (!rt) throw Error("stride run: --debug: the scene's first robot has no <controller>");
  StopSignals stop;  // before the server's thread starts, so that thread inherits the blocked set
  debug::ServerOptions options;
  options.listen = debug::parse_endpoint(run.address, "stride run: --debug");
  options.tokens = debug::tokens_from(run.token_file);
  options.log_dir = run.log_dir;
  options.robot = sim.robot(0).name();
  debug::DebugServer server(std::move(options));
  server.allow_restart();  // `restart`: the scene from its start, as `reset` and `run` do
  rt->set_frame_boundary(&server.boundary());
  out << "debug server on " << server.endpoint().text() << " serving robot " << sim.robot(0).name()
      << " (connect " << server.endpoint().text() << ")" << std::endl;
  // A console connecting a moment late must not miss the walk: it starts with the first one.
  out << "paused at t=" << sim.time() << " until the first console connects" << std::endl;
  while (!stop.requested() && server.stats().clients == 0) {
    server.idle(*rt);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!stop.requested()) out << "a console connected: running" << std::endl;

  double start = sim.time();
  double ran = 0;  // s of simulated time before the last restart
  auto wall_start = std::chrono::steady_clock::now();
  while (!stop.requested() && (!run.seconds || sim.time() - start < *run.seconds - 1e-9)) {
    if (server.take_restart()) {
      ran += sim.time() - start;
      rt->set_frame_boundary(nullptr);
      session.reset();
      rt = session.runtime(0);
      rt->set_frame_boundary(&server.boundary());
      start = sim.time();
      wall_start = std::chrono::steady_clock::now();
      out << "restarted the scene (a console asked)" << std::endl;
    }
    sim.step();
    const auto due = wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(sim.time() - start));
    std::this_thread::sleep_until(due);
  }
  rt->set_frame_boundary(nullptr);
  return ran + sim.time() - start;
}

}  // namespace stride::cli
