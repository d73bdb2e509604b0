#pragma once
// Runs a program with the given standard input and collects its standard output and error, for
// tools whose output Stride writes itself (gnuplot's PNGs go through the checked writer).
#include <string>
#include <vector>

namespace stride::console {

struct ChildResult {
  int exit_status = -1;  // the program's exit code; -1 if it was killed by a signal
  int signal = 0;        // the signal that ended it, 0 if it exited
  std::string out, err;
};

// argv[0] is looked up on PATH. Throws stride::Error if the program cannot be started.
ChildResult run_child(const std::vector<std::string>& argv, const std::string& input);

}  // namespace stride::console
