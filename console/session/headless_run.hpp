#pragma once
// A headless run the way `stride run` does it: stepping for a given simulated time with a
// progress line, stopping early and cleanly on Ctrl-C so the report still covers what ran.
#include <functional>
#include <string>

namespace stride::sim {
class Simulation;
}

namespace stride::console {

class InterruptFlag;
class ProgressLine;

struct HeadlessRun {
  double seconds = 0;                        // simulated time to run
  std::function<void()> after_step;          // e.g. the video recorder; may be empty
  const InterruptFlag* interrupt = nullptr;  // checked between physics steps
  ProgressLine* progress = nullptr;          // told the simulated seconds run
};

// Steps the simulation; returns true if the interrupt stopped it before `seconds`.
bool run_headless(sim::Simulation& sim, const HeadlessRun& run);

// `seconds` checked against [0, limits::kMaxDuration] (the console's `run` and `wait` take the same
// cap); throws stride::UsageError naming `what`.
double checked_run_seconds(double seconds, const std::string& what);

}  // namespace stride::console
