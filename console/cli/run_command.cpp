// `stride run <scene> --seconds S [--seed N] [--report out.json] [--log file] [--snapshot f.png]
// [--video walk.apng|walk.mp4|dir ...] [--view v] [--fps N] [--no-overlay] [--set
// Module.field=value ...] [--physics a=v,b=w] [--lola <socket> ...] [--debug addr:port
// [--token-file f]
// [--log-dir d]]`: a headless run, optionally with pictures and a movie, optionally with a robot
// on LoLA (lola_run.hpp), or served to debug consoles in real time (debug_run.hpp). Output paths
// are checked before the run; Ctrl-C ends the run early and still writes its report. With
// `--ensemble N [--heading-spread rad] [--position-spread m] [--jobs N]`: N perturbed starts
// (seeds N.. on) and the spread of their walks instead.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <optional>
#include <ostream>

#include "console/cli/arguments.hpp"
#include "console/cli/debug_run.hpp"
#include "console/cli/ensemble_arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/lola_run.hpp"
#include "console/cli/subcommand.hpp"
#include "console/ensemble/ensemble_report.hpp"
#include "console/output/interrupt_flag.hpp"
#include "console/output/output_paths.hpp"
#include "console/progress/progress_line.hpp"
#include "console/session/headless_run.hpp"
#include "console/session/sim_session.hpp"
#include "console/sweep/scene_edit.hpp"
#include "console/sweep/sweep_request.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"
#include "simulator/render/movie_file.hpp"
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

// Every output named on the command line, checked before anything runs.
void check_outputs(const std::string& report, const std::string& log, const std::string& snapshot,
                   const std::vector<std::string>& videos) {
  if (!report.empty()) console::check_output_file("stride run: --report", report);
  if (!log.empty()) console::check_output_file("stride run: --log", log);
  if (!snapshot.empty()) console::check_output_file("stride run: --snapshot", snapshot);
  for (const std::string& v : videos)
    if (render::is_movie_path(v))
      console::check_output_file("stride run: --video", v);
    else
      console::check_output_dir("stride run: --video", v);
}

}  // namespace

int run_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "run");
    const bool overlay = !a.flag("--no-overlay");  // before positional(), which skips values
    const std::string scene = a.positional("scene");
    const double seconds =
        console::checked_run_seconds(a.number_or("--seconds", 10.0), "stride run: --seconds");
    if (a.has("--ensemble")) return run_ensemble(a, scene, seconds, out);
    const std::optional<std::uint64_t> seed =
        a.has("--seed") ? std::optional<std::uint64_t>(a.unsigned_integer("--seed")) : std::nullopt;
    const std::string report = a.text_or("--report", "");

    const std::string log = a.text_or("--log", "");
    const std::string snapshot = a.text_or("--snapshot", "");
    const std::vector<std::string> videos = a.texts("--video");
    std::vector<ParameterOverride> overrides;
    for (const std::string& set : a.texts("--set"))
      overrides.push_back(parse_parameter_override(set, "stride run: --set"));
    std::vector<sweep::Setting> physics;  // as `stride sweep` and `experiment` take them
    if (a.has("--physics")) try {
        physics = sweep::physics_settings(a.text("--physics"));
      } catch (const Error& e) {
        throw UsageError(std::string("stride run: ") + e.what());
      }
    const std::string view = a.text_or("--view", "");
    const double fps = a.number_or("--fps", 25.0);
    DebugRun debug{a.text_or("--debug", ""), a.text_or("--token-file", ""),
                   a.text_or("--log-dir", "."),
                   a.has("--seconds") ? std::optional<double>(seconds) : std::nullopt};
    if (!(fps >= 1 && fps <= 1000))
      throw UsageError("stride run: --fps: expected 1 to 1000 frames/s");
    const LolaRunOptions lola = read_lola_options(a);
    a.finish();
    if (!debug.address.empty() && lola.any())
      throw UsageError(
          "stride run: --debug: serve the LoLA robot with 'stride robot --debug' instead");
    check_outputs(report, log, snapshot, videos);

    sim::SceneDescription description =
        physics.empty() ? sim::parse_scene_file(scene) : sweep::load_edited_scene(scene, physics);
    if (seed) description.physics.seed = *seed;
    console::add_parameter_overrides(description, overrides, "stride run: --set");
    console::SimSession session(lola_scene(std::move(description), lola));
    auto& sim = session.simulation();
    for (int i = 0; i < sim.robot_count(); ++i)
      if (const Runtime* rt = session.runtime(i))
        for (const std::string& note : console::parameter_notes(*rt))
          out << "note: " << note << "\n";
    if (!log.empty()) {
      if (!session.runtime(0)) throw Error("stride run: --log: robot 0 has no <controller>");
      session.runtime(0)->start_log(log);
    }
    render::WorldRenderer renderer;
    render::VideoRecorder recorder;
    if (!videos.empty())
      recorder.start(
          sim, videos, view,
          std::max<std::uint64_t>(1, std::llround(1.0 / (fps * sim.scene().physics.step))), 0,
          overlay);
    else if (!snapshot.empty())
      render::resolve_view(sim, view);  // a bad view fails before the run, not after it
    const auto server = attach_lola(session, lola, err);
    console::InterruptFlag interrupt;
    const auto t0 = std::chrono::steady_clock::now();
    bool interrupted = false;
    double requested = seconds;
    if (!debug.address.empty()) {
      requested = serve_simulation(session, debug, out);  // until --seconds or a signal
    } else {
      console::ProgressLine progress(
          err,
          {.label = "run", .total = seconds, .unit = "s", .decimals = 1, .rate_as_speedup = true},
          console::progress_settings());
      console::HeadlessRun run{.seconds = seconds, .interrupt = &interrupt, .progress = &progress};
      std::optional<LolaRestarts> restarts;
      if (server) try {
          restarts.emplace(session, *server, lola);
        } catch (const Error& e) {  // e.g. a socket path too long for one more suffix
          err << "lola: no restart side channel (" << e.what() << "): restart is the robot's alone"
              << std::endl;
        }
      if (recorder.active() || restarts)
        run.after_step = [&] {
          if (recorder.active()) recorder.after_step(renderer, sim);
          if (restarts) restarts->poll();
        };
      interrupted = console::run_headless(sim, run);
    }
    sim::RunTiming timing{.interrupted = interrupted, .requested_time = requested};
    timing.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (server) timing.lola = &server->report();
    out << sim::run_report_text(sim, timing);
    if (sim.robot_count() > 0 && sim.walk_metrics(0).result().steps > 0)
      out << "  one draw (seed " << sim.scene().physics.seed
          << "): `--ensemble N` gives the spread and fall count over perturbed starts\n";
    if (!report.empty()) {
      write_file(report, sim::run_report_json(sim, timing));
    }
    if (!snapshot.empty()) render::write_snapshot(renderer, sim, snapshot, view, 0, overlay);
    if (recorder.active()) {
      recorder.stop();
      out << "video: " << recorder.frames() << " frames in";
      for (const std::string& v : videos) out << " " << v;
      out << "\n";
    }
    return interrupted ? 128 + interrupt.signal() : 0;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
