#pragma once
// Runs a program with the given standard input and collects its standard output and error, for
// tools whose output Stride writes itself (gnuplot's PNGs go through the checked writer); or
// starts one that runs beside this process (a `stride-robot` on a LoLA socket) and ends it.
#include <sys/types.h>

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

// The program `name` in this process's executable's folder (e.g. the `stride-robot` built next to
// `stride`); that path whether or not the file exists.
std::string sibling_executable(const std::string& name);

// A program running beside this one, its standard output and error appended to `log`, its input
// /dev/null. It gets SIGKILL when the thread that started it ends (a sweep worker killed mid-run
// leaves no child behind); the destructor ends it (stop()) if it still runs.
class RunningChild {
 public:
  // argv[0] is a path (not looked up on PATH). Throws stride::Error if it cannot be started.
  RunningChild(const std::vector<std::string>& argv, const std::string& log);
  ~RunningChild();
  RunningChild(const RunningChild&) = delete;
  RunningChild& operator=(const RunningChild&) = delete;

  pid_t pid() const { return started_; }  // also once it ended
  // Without blocking: has it ended? Then how ("exit status 2", "killed by signal 9").
  bool ended();
  const std::string& how_it_ended() const { return how_; }
  // SIGTERM, then SIGKILL after `grace` seconds; reaps it. Returns how_it_ended().
  const std::string& stop(double grace = 2.0);

 private:
  void reaped(int status);
  pid_t pid_ = -1;      // -1 once reaped
  pid_t started_ = -1;  // the pid it had
  std::string how_;
};

}  // namespace stride::console
