#include "console/session/headless_run.hpp"

#include <cmath>
#include <cstdint>
#include <string>

#include "console/output/interrupt_flag.hpp"
#include "console/progress/progress_line.hpp"
#include "robot/core/error.hpp"
#include "robot/core/physical_limits.hpp"
#include "simulator/simulation.hpp"

namespace stride::console {

bool run_headless(sim::Simulation& sim, const HeadlessRun& run) {
  const double start = sim.time();
  const auto n = static_cast<std::uint64_t>(std::llround(run.seconds / sim.scene().physics.step));
  for (std::uint64_t k = 0; k < n; ++k) {
    if (run.interrupt && run.interrupt->raised()) return true;
    sim.step();
    if (run.after_step) run.after_step();
    if (run.progress && k % 100 == 99) run.progress->set_done(sim.time() - start);
  }
  if (run.progress) run.progress->set_done(sim.time() - start);
  return false;
}

double checked_run_seconds(double seconds, const std::string& what) {
  if (const std::string p = limits::duration_problem(seconds); !p.empty())
    throw UsageError(what + ": " + p);
  return seconds;
}

}  // namespace stride::console
