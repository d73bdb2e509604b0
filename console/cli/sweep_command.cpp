// `stride sweep <file.xml> [--jobs N] [--out dir] [--resume] [--overwrite] [--quiet]
// [--seeds N] [--scenes dir] [--set target=value ...] [--physics a=v,b=w] [--only column=a,b ...]
// [--no-plots] [--mpi] [--through-lola | --lola-packets]`: a sweep file's runs on this machine's
// cores, or on MPI ranks when mpirun/srun starts it; one CSV row per run in <out>/runs.csv and the
// tallies printed. --through-lola: each run's robot 0 controlled by a started `stride robot` over
// LoLA in lockstep; --lola-packets: by its in-process controller through LoLA's packets.
#include <filesystem>
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/sweep/sweep_request.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

// What `stride sweep` and `stride experiment` share: flags to a SweepRequest (the file aside).
sweep::SweepRequest sweep_request_flags(ArgumentReader& a, const std::string& command) {
  sweep::SweepRequest r;
  r.options.resume = a.flag("--resume");
  r.options.overwrite = a.flag("--overwrite");
  r.options.plots = !a.flag("--no-plots");
  r.quiet = a.flag("--quiet");
  r.force_mpi = a.flag("--mpi");
  r.link = sweep::link_flags(a.flag("--through-lola"), a.flag("--lola-packets"), command);
  if (a.has("--jobs")) {
    const std::uint64_t n = a.unsigned_integer("--jobs");
    if (n < 1 || n > 1024) throw Error("stride " + command + ": --jobs: expected 1..1024");
    r.jobs = static_cast<int>(n);
  }
  if (a.has("--seeds")) {
    const std::uint64_t n = a.unsigned_integer("--seeds");
    if (n < 1 || n > 100000) throw Error("stride " + command + ": --seeds: expected 1..100000");
    r.seeds = static_cast<int>(n);
  }
  r.scenes_dir = a.text_or("--scenes", "");
  for (const std::string& s : a.texts("--set")) r.settings.push_back(sweep::parse_setting(s));
  if (a.has("--physics"))
    for (sweep::Setting& s : sweep::physics_settings(a.text("--physics")))
      r.settings.push_back(std::move(s));
  for (const std::string& s : a.texts("--only")) r.options.only.push_back(sweep::parse_only(s));
  r.options.out_dir = a.text_or("--out", "");
  return r;
}

std::string command_line(const std::string& command, Args args) {
  std::string text = "stride " + command;
  for (const std::string& s : args) text += " " + s;
  return text;
}

int sweep_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "sweep");
    sweep::SweepRequest r = [&] {
      try {
        return sweep_request_flags(a, "sweep");
      } catch (const UsageError&) {
        throw;
      } catch (const Error& e) {
        throw UsageError(e.what());  // a malformed --set, --physics or --only
      }
    }();
    r.file = find_input(a.positional("sweep file"));  // also a shipped one from anywhere
    a.finish();
    if (r.options.out_dir.empty())
      r.options.out_dir = std::filesystem::path(r.file).stem().string() + "-sweep";
    r.options.command = command_line("sweep", args);
    const auto result = sweep::run_sweep_request(r, out, err);
    if (!result) return 0;  // an MPI worker rank
    if (!result->complete) return 130;
    if (result->failed == 0) return 0;
    err << "stride sweep: " << result->failed << " of " << result->selected
        << " runs failed (listed above, status 'failed' in runs.csv)\n";
    return 1;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
