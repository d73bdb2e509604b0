// `stride experiment <name> [--seeds N] [--jobs N] [--out dir] [--scenes dir] [--sweeps dir]
// [--resume] [--quiet] [--no-plots] [--set Module.field=value ...] [--physics a=v,b=w]
// [--cases a,b] [--only column=a,b ...] [--through-lola | --lola-packets]`: the thesis'
// Chapter 4 experiments. All but kalman are sweep files in scenes/experiments run by the sweep
// engine (`stride sweep` runs the same files); --jobs walks at once (default: hardware threads),
// the results do not depend on it; under mpirun the walks spread over the ranks.
#include <ostream>
#include <sstream>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/experiments/experiment_list.hpp"
#include "console/experiments/parameter_overrides.hpp"
#include "console/output/output_paths.hpp"
#include "console/sweep/sweep_request.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

int experiment_main(Args args, std::ostream& out, std::ostream& err) {
  if (asks_for_settings(args)) {
    print_module_parameters(out);
    return kExitOk;
  }
  try {
    ArgumentReader a(args, "experiment");
    experiments::ExperimentOptions o;
    o.plots = !a.flag("--no-plots");  // before positional(), which skips a flag's value
    o.resume = a.flag("--resume");
    o.quiet = a.flag("--quiet");
    o.link = sweep::link_flags(a.flag("--through-lola"), a.flag("--lola-packets"), "experiment");
    const std::string name = a.positional(
        "experiment: posture|knee-energy|kalman|fastest|arm-swing|gains|push|position-push|"
        "push-recovery|landing-control");
    if (a.has("--seeds")) {
      const std::uint64_t n = a.unsigned_integer("--seeds");
      if (n < 1 || n > 1000) throw UsageError("stride experiment: --seeds: expected 1..1000");
      o.seeds = static_cast<int>(n);
    }
    if (a.has("--jobs")) {
      const std::uint64_t n = a.unsigned_integer("--jobs");
      if (n < 1 || n > 256) throw UsageError("stride experiment: --jobs: expected 1..256");
      o.jobs = static_cast<int>(n);
    }
    o.out_dir = a.text_or("--out", "");
    o.scenes_dir = a.text_or("--scenes", "");
    o.sweeps_dir = a.text_or("--sweeps", o.sweeps_dir);
    for (const std::string& set : a.texts("--set"))
      o.parameters.push_back(experiments::parse_parameter_override(set));
    if (a.has("--physics")) {
      if (name == "kalman")
        throw UsageError(
            "stride experiment kalman: --physics: kalman replays one walk's filter; only "
            "the sweep studies take it");
      try {
        o.physics = sweep::physics_settings(a.text("--physics"));
      } catch (const Error& e) {
        throw UsageError(e.what());  // a malformed value is a wrong command line
      }
    }
    if (a.has("--cases")) {
      if (name != "posture")
        throw UsageError("stride experiment " + name + ": --cases: only posture takes it");
      std::stringstream list(a.text_or("--cases", ""));
      for (std::string item; std::getline(list, item, ',');)
        if (!item.empty()) o.cases.push_back(item);
      if (o.cases.empty())
        throw UsageError("stride experiment posture: --cases: expected a,b,... of case names");
    }
    try {
      for (const std::string& s : a.texts("--only")) o.only.push_back(sweep::parse_only(s));
    } catch (const Error& e) {
      throw UsageError(e.what());  // a malformed --only
    }
    a.finish();
    if (!o.out_dir.empty()) console::check_output_dir("stride experiment: --out", o.out_dir);
    o.command = "stride experiment";
    for (const std::string& s : args) o.command += " " + s;
    return experiments::run_experiment(name, o, out, err);
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
