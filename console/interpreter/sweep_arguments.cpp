#include "console/interpreter/sweep_arguments.hpp"

#include "console/interpreter/values.hpp"
#include "robot/core/error.hpp"

namespace stride::console {

SweepArguments parse_sweep_arguments(const std::vector<std::string>& a,
                                     const std::string& command) {
  SweepArguments r;
  const bool seeds = command == "sweep";
  for (std::size_t i = 1; i < a.size(); ++i) {
    const std::string& w = a[i];
    const bool valued = w == "jobs" || w == "out" || (seeds && w == "seeds");
    if (valued && i + 1 >= a.size()) throw Error(command + ": '" + w + "' needs a value");
    if (w == "jobs")
      r.jobs = static_cast<int>(parse_integer(a[++i], "jobs", 1, 1024));
    else if (seeds && w == "seeds")
      r.seeds = static_cast<int>(parse_integer(a[++i], "seeds", 1, 100000));
    else if (w == "out")
      r.out = a[++i];
    else if (w == "resume")
      r.resume = true;
    else if (w == "overwrite")
      r.overwrite = true;
    else if (w == "quiet")
      r.quiet = true;
    else
      throw Error(command + ": unexpected '" + w + "' (jobs N, out <dir>" +
                  (seeds ? ", seeds N" : "") + ", resume, overwrite, quiet)");
  }
  return r;
}

}  // namespace stride::console
