#pragma once
// The words after `sweep <file>` (and `tune <file>`) in the console: jobs N, out <dir>, seeds N,
// resume, overwrite, quiet. Pure parsing, so the command table can check them without the engine.
#include <string>
#include <vector>

namespace stride::console {

struct SweepArguments {
  int jobs = 0, seeds = 0;  // 0: the default
  std::string out;
  bool resume = false, overwrite = false, quiet = false;
};

// `args[0]` is the file; throws stride::Error naming the bad word. `tune` takes the same words
// but seeds (its tuning file names the training and held-out seeds).
SweepArguments parse_sweep_arguments(const std::vector<std::string>& args,
                                     const std::string& command = "sweep");

}  // namespace stride::console
