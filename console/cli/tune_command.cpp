// `stride tune <file.xml> [--jobs N] [--out dir] [--resume] [--overwrite] [--quiet] [--set
// target=value ...] [--physics a=v,b=w] [--no-plots] [--mpi]`: a search over a tuning file's
// parameters, each generation one sweep on this machine's cores or on MPI ranks, the result
// judged on the held-out walks against the thesis' values.
#include <filesystem>
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/sweep/sweep_request.hpp"
#include "console/tune/tune_run.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

std::string command_line(const std::string& command, Args args);  // sweep_command.cpp

namespace {

tune::TuneRequest tune_flags(ArgumentReader& a) {
  tune::TuneRequest r;
  r.resume = a.flag("--resume");
  r.overwrite = a.flag("--overwrite");
  r.plots = !a.flag("--no-plots");
  r.quiet = a.flag("--quiet");
  r.force_mpi = a.flag("--mpi");
  if (a.has("--jobs")) {
    const std::uint64_t n = a.unsigned_integer("--jobs");
    if (n < 1 || n > 1024) throw UsageError("stride tune: --jobs: expected 1..1024");
    r.jobs = static_cast<int>(n);
  }
  try {
    for (const std::string& s : a.texts("--set")) r.settings.push_back(sweep::parse_setting(s));
    if (a.has("--physics"))
      for (sweep::Setting& s : sweep::physics_settings(a.text("--physics")))
        r.settings.push_back(std::move(s));
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError(e.what());  // a malformed --set or --physics
  }
  r.out_dir = a.text_or("--out", "");
  return r;
}

}  // namespace

int tune_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "tune");
    tune::TuneRequest r = tune_flags(a);
    r.file = find_input(a.positional("tuning file"));
    a.finish();
    if (r.out_dir.empty()) r.out_dir = std::filesystem::path(r.file).stem().string() + "-tune";
    r.command = command_line("tune", args);
    const auto result = tune::run_tune(r, out, err);
    if (!result) return 0;  // an MPI worker rank
    return result->complete ? 0 : 130;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
