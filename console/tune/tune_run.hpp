#pragma once
// `stride tune <file>` and the console's `tune`: a search over a tuning file's parameters, each
// generation's candidates run as one sweep through the sweep engine (this process, --jobs
// workers, or MPI ranks when mpirun/srun started it), then the best candidate and the thesis'
// values judged on the held-out walks only.
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "console/sweep/sweep_spec.hpp"
#include "console/sweep/tally.hpp"
#include "console/tune/tune_output.hpp"

namespace stride::tune {

struct TuneRequest {
  std::string file;
  int jobs = 0;                          // walks at once on this machine; 0: every hardware thread
  bool force_mpi = false;                // --mpi: fail unless MPI can be used
  std::vector<sweep::Setting> settings;  // --set / --physics, before everything the file sets
  std::string out_dir;
  bool resume = false, overwrite = false, quiet = false, plots = true;
  std::string command;         // written to the manifest
  std::function<bool()> stop;  // polled: true ends the search, output left resumable
};

struct TuneResult {
  bool complete = false;              // every generation and the held-out sweep done
  int generations = 0;                // generations done (the first, random one included)
  std::size_t walks = 0, failed = 0;  // training walks, all generations
  SearchRecord best;                  // the best candidate on the training walks
  CandidateScore heldout_thesis, heldout_tuned;
  std::vector<sweep::TallyTable> heldout;  // the held-out sweep's tables
};

// The tuning file with the request's settings, checked (throws "file:line: ..." errors).
TuneSpec request_tune_spec(const TuneRequest& r);

// Runs the search; tables to `out`, progress to `err`. Throws stride::Error before any walk on a
// bad file (file:line) or an output it cannot write. On MPI ranks other than 0 it works for
// rank 0 and returns nullopt.
std::optional<TuneResult> run_tune(const TuneRequest& r, std::ostream& out, std::ostream& err);

}  // namespace stride::tune
