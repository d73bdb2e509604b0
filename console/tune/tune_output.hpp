#pragma once
// A search's output directory:
//   tune.xml               the tuning file as it was run (--resume needs the same text)
//   manifest.txt           the command and the binary's revision
//   generations/gen-NNNN/  each generation's sweep output (runs.csv: a row per walk, flushed as
//                          it ends; --resume continues a cut generation there)
//   search.csv             a row per candidate: generation, its parameters, objective, walks,
//                          failed, the best objective so far (rewritten after each generation)
//   heldout/               the held-out sweep (thesis against tuned, the held-out walks only)
//   results.txt            which parameters moved and the held-out comparison; search.png,
//                          heldout.png and their CSVs
// Everything is checked writable before any walk runs.
#include <string>
#include <vector>

#include "console/tune/tune_spec.hpp"
#include "console/tune/tune_sweeps.hpp"

namespace stride::tune {

// One evaluated candidate of the search.
struct SearchRecord {
  int generation = 0;
  std::string label;
  std::vector<double> values;
  CandidateScore score;
};

class TuneOutput {
 public:
  // Creates `dir`. Fresh: refuses a directory holding a search unless `overwrite` (which clears
  // it); resume: needs the same tuning file text there. Throws stride::Error naming the path.
  TuneOutput(const std::string& dir, const std::string& file_text, bool resume, bool overwrite,
             const std::string& command);

  const std::string& dir() const { return dir_; }
  std::string generation_dir(int generation) const;
  std::string heldout_dir() const;
  // search.csv from every candidate so far.
  void write_search(const TuneSpec& tune, const std::vector<SearchRecord>& records) const;
  // <dir>/<name> whole, through a temporary file and a rename.
  void write_file(const std::string& name, const std::string& text) const;

 private:
  std::string dir_;
};

}  // namespace stride::tune
