#pragma once
// The console's `sweep <file> [jobs N] [out <dir>] [resume] [seeds N] [quiet]`: the same engine
// and output as `stride sweep`, and the tallies kept as keys a script can `get` and `expect`:
//   sweep.runs  sweep.failed  sweep.complete  sweep.<tally>.<column>[<group>]
// (<group> is the tally's `by` values joined by '/', e.g. sweep.cases.kept[hip_medium]; a number
// is its full value, not the table's rounded text).
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stride::console {

struct SweepState;  // the last sweep's result

class SweepCommand {
 public:
  SweepCommand();
  ~SweepCommand();
  // Runs a sweep; `base_dir` resolves a relative file (the running script's directory first).
  void run(const std::vector<std::string>& args, const std::string& file, std::ostream& out,
           bool interactive);
  // The value of a sweep.* key; throws stride::Error for an unknown one or before any sweep.
  std::string value(const std::string& key) const;

 private:
  std::unique_ptr<SweepState> last_;
};

}  // namespace stride::console
