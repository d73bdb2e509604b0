#pragma once
// The summary of a headless run: timing, the state hash, and each robot's torso and fall state.
#include <string>

#include "simulator/lola/lola_server.hpp"
#include "simulator/simulation.hpp"

namespace stride::sim {

struct RunTiming {
  double wall_time = 0;                   // s
  const LolaServeReport* lola = nullptr;  // a robot served over LoLA: its frames, missed, lost
  bool interrupted = false;               // stopped early (Ctrl-C): the report covers what ran
  double requested_time = 0;              // s, the run asked for (reported when interrupted)
};

std::string run_report_json(const Simulation& sim, const RunTiming& timing);
std::string run_report_text(const Simulation& sim, const RunTiming& timing);
std::string hash_hex(std::uint64_t h);
// "exact", or "iterative <n>" (with " sor <w>" when not ODE's 1.3).
std::string solver_text(const PhysicsSettings& physics);

}  // namespace stride::sim
