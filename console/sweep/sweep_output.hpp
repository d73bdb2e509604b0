#pragma once
// A sweep's output directory:
//   runs.csv       one row per run, appended and flushed as each run ends (sorted by run id once
//                  the sweep is complete); --resume reads it and runs only what it lacks
//   sweep.xml      the sweep file as it was run (sweep.txt: the spec, for sweeps built in code)
//   manifest.txt   the binary's revision, the command, the plan's fingerprint (resume checks it)
//   timing.csv     per run: wall seconds, attempts, worker (not part of the results)
//   .lock          held (flock) while a sweep writes here: a second one is refused
//   tallies.txt, <tally>.csv, <plot>.png/.csv, traces/run-<id>.csv
// Everything is checked writable before any run starts.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "console/sweep/output_lock.hpp"
#include "console/sweep/run_row.hpp"
#include "console/sweep/sweep.hpp"

namespace stride::sweep {

// Output files, shared with the tuner's output (console/tune/tune_output.hpp): a file's whole
// text ("" when it cannot be read); a directory created with its parents (throws "--out: cannot
// create directory ..."); a file written whole through a temporary file and a rename (throws
// "cannot write ...", leaving no half-written file).
std::string read_whole_file(const std::string& path);
void create_output_dir(const std::string& dir);
void write_whole_file(const std::string& path, const std::string& text);

// FNV-1a over the header and every run's settings and plan cells: equal plans, equal prints.
std::string plan_fingerprint(const Sweep& sweep);

class SweepOutput {
 public:
  // Creates `dir` (and its parents). Fresh: refuses a directory that already has a runs.csv
  // unless `overwrite`. Resume: reads the rows there after checking the manifest's fingerprint
  // and the header; an unfinished last line (a killed sweep) is dropped. Throws stride::Error
  // naming the path and the reason; writes nothing on error.
  SweepOutput(const Sweep& sweep, const std::string& dir, bool resume, bool overwrite,
              const std::string& command);
  ~SweepOutput();
  SweepOutput(const SweepOutput&) = delete;
  SweepOutput& operator=(const SweepOutput&) = delete;

  const std::string& dir() const { return dir_; }
  // Rows already there (resume), by run id, as CSV cells.
  const std::map<std::int64_t, std::vector<std::string>>& rows() const { return rows_; }

  // Appends the run's CSV row (and its trace and timing) with one write each, flushed; a trace
  // it cannot write turns the row into a failed one.
  void add(RunRow& row, int worker);
  // Rewrites runs.csv sorted by run id (through a temporary file and a rename).
  void sort_rows();
  // Writes <dir>/<name> whole, through a temporary file and a rename.
  void write_file(const std::string& name, const std::string& text) const;

 private:
  void append(int fd, const std::string& text, const std::string& what);

  const Sweep& sweep_;
  std::string dir_;
  std::optional<OutputLock> lock_;
  std::map<std::int64_t, std::vector<std::string>> rows_;
  int runs_fd_ = -1, timing_fd_ = -1;
};

}  // namespace stride::sweep
