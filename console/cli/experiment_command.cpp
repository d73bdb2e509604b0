// `stride experiment <name> [--seeds N] [--jobs N] [--out dir] [--scenes dir] [--no-plots]
// [--set Module.field=value ...]`: the
// thesis' Chapter 4 experiments run in the simulator (posture, knee-energy, kalman, fastest,
// arm-swing, gains); --jobs walks at once (default: hardware threads), the results do not depend
// on it.
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/subcommand.hpp"
#include "console/experiments/experiment_list.hpp"
#include "console/experiments/parameter_overrides.hpp"
#include "console/experiments/walk_pool.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

int experiment_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "experiment");
    experiments::ExperimentOptions o;
    o.plots = !a.flag("--no-plots");  // before positional(), which skips a flag's value
    const std::string name =
        a.positional("experiment: posture|knee-energy|kalman|fastest|arm-swing|gains");

    if (a.has("--seeds")) {
      const std::uint64_t n = a.unsigned_integer("--seeds");
      if (n < 1 || n > 1000) throw Error("stride experiment: --seeds: expected 1..1000");
      o.seeds = static_cast<int>(n);
    }
    o.jobs = experiments::default_jobs();
    if (a.has("--jobs")) {
      const std::uint64_t n = a.unsigned_integer("--jobs");
      if (n < 1 || n > 256) throw Error("stride experiment: --jobs: expected 1..256");
      o.jobs = static_cast<int>(n);
    }
    o.out_dir = a.text_or("--out", "");
    o.scenes_dir = a.text_or("--scenes", o.scenes_dir);
    for (const std::string& set : a.texts("--set"))
      o.parameters.push_back(experiments::parse_parameter_override(set));
    a.finish();
    return experiments::run_experiment(name, o, out);
  } catch (const Error& e) {
    err << e.what() << "\n";
    return 1;
  }
}

}  // namespace stride::cli
