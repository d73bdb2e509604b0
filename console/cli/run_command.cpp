// `stride run <scene> --seconds S [--seed N] [--report out.json] [--log file] [--snapshot f.png]
// [--video dir] [--view v] [--fps N] [--lola <socket> ...]`: a headless run, optionally with
// pictures, optionally with a robot on LoLA (lola_run.hpp). With `--ensemble N
// [--heading-spread rad] [--position-spread m] [--jobs N]`: N perturbed starts (seeds N.. on)
// and the spread of their walks instead.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/ensemble_arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/lola_run.hpp"
#include "console/cli/subcommand.hpp"
#include "console/ensemble/ensemble_report.hpp"
#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"
#include "robot/model/physical_limits.hpp"
#include "simulator/render/snapshot.hpp"
#include "simulator/render/views.hpp"
#include "simulator/run_report.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace stride::cli {
namespace {

int run_ensemble(ArgumentReader& a, const std::string& scene, double seconds, std::ostream& out) {
  const std::uint64_t n = a.unsigned_integer("--ensemble");
  if (n < 1 || n > 1000) throw Error("stride run: --ensemble: expected 1..1000 starts");
  for (const char* single : {"--report", "--log", "--snapshot", "--video", "--view", "--fps"})
    if (a.has(single))
      throw UsageError(std::string("stride run: ") + single +
                       ": not with --ensemble (one run only)");
  ensemble::EnsembleRequest r{
      scene, {}, read_ensemble_spec(a, "run", static_cast<int>(n)), seconds};
  const int jobs = read_jobs(a, "run");
  a.finish();
  const auto members = ensemble::run_ensembles({r}, jobs).front();
  ensemble::print_ensemble(r, members, out);
  return 0;
}

}  // namespace

int run_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "run");
    const std::string scene = a.positional("scene");
    const double seconds = a.number_or("--seconds", 10.0);
    if (const std::string p = limits::duration_problem(seconds); !p.empty())
      throw UsageError("stride run: --seconds: " + p);
    if (a.has("--ensemble")) return run_ensemble(a, scene, seconds, out);
    const std::optional<std::uint64_t> seed =
        a.has("--seed") ? std::optional<std::uint64_t>(a.unsigned_integer("--seed")) : std::nullopt;
    const std::string report = a.text_or("--report", "");

    const std::string log = a.text_or("--log", "");
    const std::string snapshot = a.text_or("--snapshot", "");
    const std::string video = a.text_or("--video", "");
    const std::string view = a.text_or("--view", "");
    const double fps = a.number_or("--fps", 25.0);
    if (!(fps >= 1 && fps <= 1000))
      throw UsageError("stride run: --fps: expected 1 to 1000 frames/s");
    const LolaRunOptions lola = read_lola_options(a);
    a.finish();

    sim::SceneDescription description = sim::parse_scene_file(scene);
    if (seed) description.physics.seed = *seed;
    console::SimSession session(lola_scene(std::move(description), lola));
    auto& sim = session.simulation();
    if (!log.empty()) {
      if (!session.runtime(0)) throw Error("stride run: --log: robot 0 has no <controller>");
      session.runtime(0)->start_log(log);
    }
    render::WorldRenderer renderer;
    render::VideoRecorder recorder;
    if (!video.empty())
      recorder.start(
          sim, video, view,
          std::max<std::uint64_t>(1, std::llround(1.0 / (fps * sim.scene().physics.step))));
    else if (!snapshot.empty())
      render::resolve_view(sim, view);  // a bad view fails before the run, not after it
    const auto server = attach_lola(session, lola, err);
    const auto t0 = std::chrono::steady_clock::now();
    if (recorder.active())
      sim.run_for(seconds, [&] { recorder.after_step(renderer, sim); });
    else
      sim.run_for(seconds);
    sim::RunTiming timing;
    timing.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (server) timing.lola = &server->report();
    out << sim::run_report_text(sim, timing);
    if (sim.robot_count() > 0 && sim.walk_metrics(0).result().steps > 0)
      out << "  one draw (seed " << sim.scene().physics.seed
          << "): `--ensemble N` gives the spread and fall count over perturbed starts\n";
    if (!report.empty()) {
      write_file(report, sim::run_report_json(sim, timing));
    }
    if (!snapshot.empty()) render::write_snapshot(renderer, sim, snapshot, view);
    if (recorder.active()) out << "video: " << recorder.frames() << " frames in " << video << "\n";
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
