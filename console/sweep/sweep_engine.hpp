#pragma once
// The one engine every scene-file experiment runs on:
//
//   sweep::Sweep sweep(sweep::parse_sweep_file("scenes/experiments/posture.sweep.xml"));
//   sweep::Tallies tallies(sweep);                 // both throw file:line errors, nothing runs
//   auto executor = sweep::worker_process_executor(2);
//   sweep::SweepResult r = sweep::run_sweep(sweep, tallies, *executor, options, std::cout);
//
// A spec built in code (SweepSpec) works the same; run_rows() gives just the rows, no files.
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "console/sweep/executor.hpp"
#include "console/sweep/sweep.hpp"
#include "console/sweep/tally.hpp"

namespace stride::sweep {

struct SweepOptions {
  std::string out_dir;     // empty: no files (tallies are still computed and printed)
  bool resume = false;     // run only what out_dir/runs.csv lacks
  bool overwrite = false;  // start again in an out_dir that already has runs
  bool print_tallies = true;
  bool plots = true;  // PNGs of the sweep's <plot>s (needs gnuplot)
  // Runs whose plan column has one of these texts (each column's list must match), e.g.
  // {"case", {"hip_slow", "hip_fast"}}; ids stay those of the whole plan.
  std::vector<std::pair<std::string, std::vector<std::string>>> only;
  std::string command;  // written to the manifest
  // After each run: runs done (this time and resumed), failed, selected in all.
  std::function<void(std::size_t done, std::size_t failed, std::size_t total)> progress;
  std::function<void()> tick;  // nothing happened for a while (a progress line may redraw)
  std::function<bool()> stop;  // polled; true ends the sweep early, output left resumable
};

struct SweepResult {
  std::size_t selected = 0;                    // runs the sweep was to make
  std::size_t resumed = 0;                     // of them found done in out_dir
  std::size_t ran = 0;                         // made now
  std::size_t failed = 0;                      // failed rows in all
  bool complete = false;                       // every selected run has a row
  std::vector<std::vector<std::string>> rows;  // CSV cells of every selected run done, by run id
  std::vector<TallyTable> tallies;
};

// Throws stride::Error before any run when the output cannot be written or resumed, or a filter
// names no column or level; a failing run is a failed row, never an exception.
SweepResult run_sweep(const Sweep& sweep, const Tallies& tallies, Executor& executor,
                      const SweepOptions& options, std::ostream& out);

// The plan indices `only` keeps (all of them for an empty list).
std::vector<std::size_t> select_runs(
    const Sweep& sweep, const std::vector<std::pair<std::string, std::vector<std::string>>>& only);

// Ctrl-C and SIGTERM set a flag while a sweep runs instead of ending the process (a second one
// ends it); `interrupted()` reads the flag. Restores the previous handlers when destroyed.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  static bool interrupted();
};

}  // namespace stride::sweep
