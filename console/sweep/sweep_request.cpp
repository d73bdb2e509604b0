#include "console/sweep/sweep_request.hpp"

#include <optional>
#include <ostream>

#include "console/sweep/factor_parser.hpp"
#include "console/sweep/mpi_executor.hpp"
#include "console/sweep/run_progress.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "robot/core/error.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::sweep {
namespace {

SweepResult run_here(const SweepRequest& r, const Sweep& sweep, Executor& executor,
                     std::ostream& out, std::ostream& err) {
  const Tallies tallies(sweep);
  SweepOptions o = r.options;
  RunProgress progress(err, "sweep " + sweep.spec().name, r.quiet);
  InterruptGuard guard;
  o.progress = [&](std::size_t done, std::size_t failed, std::size_t total) {
    progress.update(done, failed, total);
  };
  o.tick = [&] { progress.tick(); };
  o.stop = [&] { return InterruptGuard::interrupted() || (r.options.stop && r.options.stop()); };
  // Printed even with --quiet: these runs will be failed rows, which a user must not miss.
  for (const std::string& scene : sweep.unloadable_scenes())
    err << "sweep " << sweep.spec().name
        << ": warning: scene does not load, its runs will fail: " << scene << "\n";
  if (!r.quiet)
    err << "sweep " << sweep.spec().name << ": " << sweep.plan().runs.size() << " runs planned, "
        << executor.describe() << (o.out_dir.empty() ? "" : ", output " + o.out_dir) << "\n";
  SweepResult result = run_sweep(sweep, tallies, executor, o, out);
  progress.finish();
  return result;
}

}  // namespace

Sweep checked_sweep(const SweepRequest& r) {
  Sweep sweep(request_spec(r), false);
  sweep.check_scenes(select_runs(sweep, r.options.only));
  return sweep;
}

Setting parse_setting(const std::string& text) {
  const std::size_t at = text.find('@');
  const std::size_t eq = text.find('=', at == std::string::npos ? 0 : at);
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw Error("--set '" + text +
                "': expected target=value (e.g. PatternWalk.steps=6, "
                "scene:physics@iterations=40)");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::vector<Setting> physics_settings(const std::string& text) {
  std::vector<Setting> out;
  try {
    for (const auto& [name, value] : sim::parse_physics_setting(text))
      out.push_back({"scene:physics@" + name, value});
  } catch (const Error& e) {
    throw Error(std::string("--physics: ") + e.what());
  }
  return out;
}

RobotLink link_flags(bool through_lola, bool packets, const std::string& command) {
  if (through_lola && packets)
    throw Error("stride " + command + ": --through-lola and --lola-packets: expected one of them");
  return through_lola ? RobotLink::Lola : packets ? RobotLink::Packets : RobotLink::InProcess;
}

std::pair<std::string, std::vector<std::string>> parse_only(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw Error("--only '" + text + "': expected column=level[,level...]");
  return {text.substr(0, eq), split_list(text.substr(eq + 1))};
}

SweepSpec request_spec(const SweepRequest& r) {
  SweepSpec spec = parse_sweep_file(r.file);
  if (r.seeds > 0) {
    spec.seeds.clear();
    for (int s = 1; s <= r.seeds; ++s) spec.seeds.push_back(static_cast<std::uint64_t>(s));
  }
  if (!r.scenes_dir.empty()) spec.scene_dir = r.scenes_dir;
  spec.settings.insert(spec.settings.begin(), r.settings.begin(), r.settings.end());
  spec.robot_link = r.link;
  return spec;
}

std::optional<SweepResult> run_sweep_request(const SweepRequest& r, std::ostream& out,
                                             std::ostream& err) {
  if (!(r.force_mpi || started_by_mpi_launcher())) {
    const Sweep sweep = checked_sweep(r);
    const int jobs = r.jobs > 0 ? r.jobs : hardware_jobs();
    auto executor = jobs == 1 ? in_process_executor() : worker_process_executor(jobs);
    return run_here(r, sweep, *executor, out, err);
  }
  if (!mpi_built()) throw Error(mpi_missing_text());
  MpiSession mpi;
  if (mpi.rank() != 0) {
    // Every rank reads the same file; if it is bad, rank 0 says so and stops the others.
    std::optional<Sweep> sweep;
    try {
      sweep.emplace(request_spec(r));
    } catch (const Error&) {
    }
    mpi_worker(mpi, [&](std::size_t i) {
      RunRow failed;
      failed.run = static_cast<std::int64_t>(i);
      if (sweep) return sweep->run(i);
      failed.reason = "rank could not load the sweep";
      return failed;
    });
    return std::nullopt;
  }
  auto executor = mpi_coordinator(mpi);  // tells the other ranks to stop when it goes
  const Sweep sweep = checked_sweep(r);
  return run_here(r, sweep, *executor, out, err);
}

}  // namespace stride::sweep
