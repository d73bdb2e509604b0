#pragma once
// `stride run <scene> --debug <addr:port>`: the simulation as a robot to debug. Its first
// robot's controller gets a debug server and the run is paced to the wall clock, as a robot's
// loop is, until --seconds (if given) or SIGINT/SIGTERM.
#include <iosfwd>
#include <optional>
#include <string>

#include "console/session/sim_session.hpp"

namespace stride::cli {

struct DebugRun {
  std::string address;     // host:port (loopback unless a token is given)
  std::string token_file;  // else STRIDE_TOKEN
  std::string log_dir = ".";
  std::optional<double> seconds;
};

// Serves until done, then returns the seconds simulated; throws stride::Error (one line).
double serve_simulation(console::SimSession& session, const DebugRun& run, std::ostream& out);

}  // namespace stride::cli
