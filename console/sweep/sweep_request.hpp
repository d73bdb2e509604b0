#pragma once
// One sweep as a command asks for it (`stride sweep`, `stride experiment <name>`, the console's
// `sweep`): the file with command-line overrides, where it runs (this process, --jobs workers,
// MPI when mpirun or srun started it), progress, and its output.
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "console/sweep/sweep_engine.hpp"

namespace stride::sweep {

struct SweepRequest {
  std::string file;
  int jobs = 0;                   // runs at once on this machine; 0: every hardware thread
  bool force_mpi = false;         // --mpi: fail unless MPI can be used
  int seeds = 0;                  // >0: seeds 1..seeds instead of the file's
  std::string scenes_dir;         // non-empty: scenes resolve here instead of the file's directory
  std::vector<Setting> settings;  // --set target=value, before everything the file sets
  SweepOptions options;
  bool quiet = false;                     // no progress lines
  RobotLink link = RobotLink::InProcess;  // --through-lola, --lola-packets
};

// --through-lola / --lola-packets (at most one) as a link; `command` names the command in the
// error for both.
RobotLink link_flags(bool through_lola, bool packets, const std::string& command);

// "PatternWalk.steps=6", "scene:robot/motor[name=pitch]@gain=50" -> Setting; throws on text
// without a target or value.
Setting parse_setting(const std::string& text);
// --physics "engine=mujoco,solver=exact" -> scene:physics@engine=mujoco,
// scene:physics@solver=exact: a physics setting (as `stride converge --settings` takes one) over
// every run's <physics>, each value checked as a scene's would be; throws on a bad setting.
std::vector<Setting> physics_settings(const std::string& text);
// "case=hip_slow,hip_fast" -> {"case", {"hip_slow", "hip_fast"}}
std::pair<std::string, std::vector<std::string>> parse_only(const std::string& text);

// The sweep file with the request's overrides, checked (throws "file:line: ..." errors).
SweepSpec request_spec(const SweepRequest& r);

// The request's sweep, its selected runs' scenes loaded once to find bad settings and keys.
Sweep checked_sweep(const SweepRequest& r);

// Runs the request; prints the tallies to `out`, progress to `err`. On MPI ranks other than 0 it
// works for rank 0 and returns nullopt. Throws stride::Error before any run on bad input.
std::optional<SweepResult> run_sweep_request(const SweepRequest& r, std::ostream& out,
                                             std::ostream& err);

}  // namespace stride::sweep
