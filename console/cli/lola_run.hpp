#pragma once
// `stride run <scene> --lola <socket> [--robot <name>] [--realtime] [--lola-wait S]`: one
// simulated NAO served over a LoLA socket instead of its in-process controller; and
// `--lola-packets` [--robot <name>]: its in-process controller through LoLA's packets (the
// float32 reference a lockstep LoLA run equals bit for bit).
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

#include "console/cli/arguments.hpp"
#include "console/session/sim_session.hpp"
#include "simulator/lola/lola_restart_listener.hpp"
#include "simulator/lola/lola_server.hpp"

namespace stride::cli {

struct LolaRunOptions {
  std::string socket;     // --lola
  bool packets = false;   // --lola-packets
  std::string robot;      // --robot (default: the scene's first)
  bool realtime = false;  // --realtime
  double wait = 30;       // --lola-wait: s for the first client
  bool any() const { return !socket.empty() || packets; }
};

LolaRunOptions read_lola_options(ArgumentReader& a);

// The scene as the options want it: the LoLA robot gets LoLA's 12 ms period unless its scene
// states a period, and (with --lola) no in-process controller: the client is its controller.
sim::SceneDescription lola_scene(sim::SceneDescription scene, const LolaRunOptions& o);

// Attaches the LoLA robot's link to a session built from lola_scene(): a server that has waited
// for its first client (--lola; returned), or the packet link (--lola-packets; nullptr).
std::unique_ptr<sim::LolaServer> attach_lola(console::SimSession& session, const LolaRunOptions& o,
                                             std::ostream& events);

// The restart side channel beside --lola's socket (robot/hal/lola/simulator_restart.hpp): when
// the client's controller restarts, the scene goes back to its start with the link attached again.
class LolaRestarts {
 public:
  LolaRestarts(console::SimSession& session, sim::LolaServer& server, const LolaRunOptions& o);
  // Between steps: true when a restart was asked and done.
  bool poll();

 private:
  console::SimSession& session_;
  sim::LolaServer& server_;
  int robot_;
  sim::LolaRestartListener listener_;
};

}  // namespace stride::cli
