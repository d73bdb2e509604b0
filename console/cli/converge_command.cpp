// `stride converge <scene> [--settings "a b ..."] [--reference S] [--starts N] [--seconds S]
// [--seed N] [--heading-spread rad] [--position-spread m] [--tolerance r] [--lost-tolerance n]
// [--jobs N] [--out dir] [--no-plots]`: the scene's walk over solver settings, each an ensemble of
// perturbed starts, and the cheapest setting that agrees with the reference.
#include <algorithm>
#include <ostream>
#include <sstream>

#include "console/cli/arguments.hpp"
#include "console/cli/ensemble_arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/ensemble/converge_study.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

int converge_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "converge");
    ensemble::ConvergeOptions o;
    o.files.plots = !a.flag("--no-plots");
    o.scene = a.positional("scene");
    std::stringstream list(a.text_or("--settings", ""));
    for (std::string s; list >> s;) o.settings.push_back(s);
    if (o.settings.empty()) o.settings = ensemble::default_settings();
    if (a.has("--reference")) {
      const std::string r = a.text("--reference");
      const auto it = std::find(o.settings.begin(), o.settings.end(), r);
      if (it == o.settings.end())
        throw UsageError("stride converge: --reference: '" + r + "' is not one of --settings");
      o.reference = static_cast<int>(it - o.settings.begin());
    }
    const std::uint64_t starts = a.has("--starts") ? a.unsigned_integer("--starts") : 16;
    if (starts < 1 || starts > 1000)
      throw UsageError("stride converge: --starts: expected 1..1000");
    o.spec = read_ensemble_spec(a, "converge", static_cast<int>(starts));
    o.seconds = a.number_or("--seconds", o.seconds);
    if (!(o.seconds > 0 && o.seconds <= 3600))
      throw UsageError("stride converge: --seconds: expected a time in (0, 3600] s");
    o.tolerance.distance = a.number_or("--tolerance", o.tolerance.distance);
    if (!(o.tolerance.distance >= 0 && o.tolerance.distance < 1))
      throw UsageError("stride converge: --tolerance: expected a fraction in [0, 1)");
    if (a.has("--lost-tolerance"))
      o.tolerance.lost =
          static_cast<int>(std::min<std::uint64_t>(a.unsigned_integer("--lost-tolerance"), 1000));
    o.jobs = read_jobs(a, "converge");
    o.files.out_dir = a.text_or("--out", "");
    a.finish();
    ensemble::run_convergence_study(o, out);
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
