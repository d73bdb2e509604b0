#pragma once
// The console's `tune <file> [jobs N] [out <dir>] [resume] [overwrite] [quiet]`: the same search
// and output as `stride tune`, and its outcome kept as keys a script can `get` and `expect`:
//   tune.generations  tune.walks  tune.failed  tune.complete  tune.best (training objective)
//   tune.heldout.thesis  tune.heldout.tuned  (held-out mean objective; .._sd their spread)
//   tune.param.<name>  (the tuned value)
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace stride::console {

struct TuneState;  // the last search's result

class TuneCommand {
 public:
  TuneCommand();
  ~TuneCommand();
  // Runs a search; `file` already resolved against the running script's directory.
  void run(const std::vector<std::string>& args, const std::string& file, std::ostream& out,
           bool interactive);
  // The value of a tune.* key; throws stride::Error for an unknown one or before any search.
  std::string value(const std::string& key) const;

 private:
  std::unique_ptr<TuneState> last_;
};

}  // namespace stride::console
