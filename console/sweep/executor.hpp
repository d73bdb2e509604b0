#pragma once
// Where a sweep's runs happen, chosen at run time: in this process, in local worker processes,
// or on MPI ranks. All give the same rows: every run builds its own world from the plan, and ODE's
// solver order is seeded per world, so neither worker nor order changes a result.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "console/sweep/run_row.hpp"

namespace stride::sweep {

using RunFunction = std::function<RunRow(std::size_t index)>;

struct ExecutorEvents {
  // A finished run (ok or failed), in the calling process, in completion order; `worker` names
  // where it ran (0-based).
  std::function<void(RunRow&& row, int worker)> done;
  // Polled between events (at least every ~0.2 s): true stops handing out runs; runs in flight
  // are abandoned (their workers ended), so the output holds only whole runs.
  std::function<bool()> stop;
  // Called when nothing happened for a while, so a progress line can redraw.
  std::function<void()> idle;
};

class Executor {
 public:
  virtual ~Executor() = default;
  virtual std::string describe() const = 0;  // "1 process", "2 worker processes", ...
  virtual int workers() const = 0;
  // Runs plan indices `todo` with `run`. A worker that dies loses only its current run, which is
  // given once more to a fresh worker; a second death makes it a failed row saying so.
  virtual void execute(const std::vector<std::size_t>& todo, const RunFunction& run,
                       const ExecutorEvents& events) = 0;
};

// --jobs 1: one run after the other in this process (a crashing run ends the sweep).
std::unique_ptr<Executor> in_process_executor();
// --jobs N: N forked worker processes, each run handed to the next free one.
std::unique_ptr<Executor> worker_process_executor(int workers);

// The machine's hardware threads (at least 1): the default for --jobs.
int hardware_jobs();

}  // namespace stride::sweep
