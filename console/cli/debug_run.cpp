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
  rt->set_frame_boundary(&server.boundary());
  out << "debug server on " << server.endpoint().text() << " serving robot " << sim.robot(0).name()
      << " (connect " << server.endpoint().text() << ")" << std::endl;

  const double start = sim.time();
  const auto wall_start = std::chrono::steady_clock::now();
  while (!stop.requested() && (!run.seconds || sim.time() - start < *run.seconds - 1e-9)) {
    sim.step();
    const auto due = wall_start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                      std::chrono::duration<double>(sim.time() - start));
    std::this_thread::sleep_until(due);
  }
  rt->set_frame_boundary(nullptr);
  return sim.time() - start;
}

}  // namespace stride::cli
