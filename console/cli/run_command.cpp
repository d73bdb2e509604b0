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
#include <string>
#include <vector>

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
#include "simulator/report/run_report.hpp"
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

// Everything a single run takes from its command line.
struct RunOptions {
  std::string scene;
  double seconds = 10;
  bool overlay = true;
  std::optional<std::uint64_t> seed;
  std::string report, log, snapshot, view;
  std::vector<std::string> videos;
  std::vector<ParameterOverride> overrides;
  std::vector<sweep::Setting> physics;  // as `stride sweep` and `experiment` take them
  double fps = 25;
  DebugRun debug;
  LolaRunOptions lola;
};

RunOptions read_run_options(ArgumentReader& a, RunOptions o) {
  o.seed =
      a.has("--seed") ? std::optional<std::uint64_t>(a.unsigned_integer("--seed")) : std::nullopt;
  o.report = a.text_or("--report", "");
  o.log = a.text_or("--log", "");
  o.snapshot = a.text_or("--snapshot", "");
  o.videos = a.texts("--video");
  for (const std::string& set : a.texts("--set"))
    o.overrides.push_back(parse_parameter_override(set, "stride run: --set"));
  if (a.has("--physics")) try {
      o.physics = sweep::physics_settings(a.text("--physics"));
    } catch (const Error& e) {
      throw UsageError(std::string("stride run: ") + e.what());
    }
  o.view = a.text_or("--view", "");
  o.fps = a.number_or("--fps", 25.0);
  o.debug =
      DebugRun{a.text_or("--debug", ""), a.text_or("--token-file", ""), a.text_or("--log-dir", "."),
               a.has("--seconds") ? std::optional<double>(o.seconds) : std::nullopt};
  if (!(o.fps >= 1 && o.fps <= 1000))
    throw UsageError("stride run: --fps: expected 1 to 1000 frames/s");
  o.lola = read_lola_options(a);
  a.finish();
  if (!o.debug.address.empty() && o.lola.any())
    throw UsageError(
        "stride run: --debug: serve the LoLA robot with 'stride robot --debug' instead");
  check_outputs(o.report, o.log, o.snapshot, o.videos);
  return o;
}

sim::SceneDescription run_scene(const RunOptions& o) {
  sim::SceneDescription description = o.physics.empty()
                                          ? sim::parse_scene_file(o.scene)
                                          : sweep::load_edited_scene(o.scene, o.physics);
  if (o.seed) description.physics.seed = *o.seed;
  console::add_parameter_overrides(description, o.overrides, "stride run: --set");
  return lola_scene(std::move(description), o.lola);
}

// Parameter notes of every controller, and robot 0's log started.
void prepare_session(console::SimSession& session, const RunOptions& o, std::ostream& out) {
  auto& sim = session.simulation();
  for (int i = 0; i < sim.robot_count(); ++i)
    if (const Runtime* rt = session.runtime(i))
      for (const std::string& note : console::parameter_notes(*rt)) out << "note: " << note << "\n";
  if (!o.log.empty()) {
    if (!session.runtime(0)) throw Error("stride run: --log: robot 0 has no <controller>");
    session.runtime(0)->start_log(o.log);
  }
}

// The run to --seconds with a progress line, videos and LoLA restarts; true if interrupted.
bool run_to_end(console::SimSession& session, const RunOptions& o, sim::LolaServer* server,
                render::WorldRenderer& renderer, render::VideoRecorder& recorder,
                console::InterruptFlag& interrupt, std::ostream& err) {
  auto& sim = session.simulation();
  console::ProgressLine progress(
      err,
      {.label = "run", .total = o.seconds, .unit = "s", .decimals = 1, .rate_as_speedup = true},
      console::progress_settings());
  console::HeadlessRun run{.seconds = o.seconds, .interrupt = &interrupt, .progress = &progress};
  std::optional<LolaRestarts> restarts;
  if (server) try {
      restarts.emplace(session, *server, o.lola);
    } catch (const Error& e) {  // e.g. a socket path too long for one more suffix
      err << "lola: no restart side channel (" << e.what() << "): restart is the robot's alone"
          << std::endl;
    }
  if (recorder.active() || restarts)
    run.after_step = [&] {
      if (recorder.active()) recorder.after_step(renderer, sim);
      if (restarts) restarts->poll();
    };
  return console::run_headless(sim, run);
}

// The report, the snapshot and the video, after the run.
void write_outcome(sim::Simulation& sim, const RunOptions& o, const sim::RunTiming& timing,
                   render::WorldRenderer& renderer, render::VideoRecorder& recorder,
                   std::ostream& out) {
  out << sim::run_report_text(sim, timing);
  if (sim.robot_count() > 0 && sim.walk_metrics(0).result().steps > 0)
    out << "  one draw (seed " << sim.scene().physics.seed
        << "): `--ensemble N` gives the spread and fall count over perturbed starts\n";
  if (!o.report.empty()) {
    write_file(o.report, sim::run_report_json(sim, timing));
  }
  if (!o.snapshot.empty()) render::write_snapshot(renderer, sim, o.snapshot, o.view, 0, o.overlay);
  if (recorder.active()) {
    recorder.stop();
    out << "video: " << recorder.frames() << " frames in";
    for (const std::string& v : o.videos) out << " " << v;
    out << "\n";
  }
}

int run_once(const RunOptions& o, std::ostream& out, std::ostream& err) {
  console::SimSession session(run_scene(o));
  auto& sim = session.simulation();
  prepare_session(session, o, out);
  render::WorldRenderer renderer;
  render::VideoRecorder recorder;
  if (!o.videos.empty())
    recorder.start(
        sim, o.videos, o.view,
        std::max<std::uint64_t>(1, std::llround(1.0 / (o.fps * sim.scene().physics.step))), 0,
        o.overlay);
  else if (!o.snapshot.empty())
    render::resolve_view(sim, o.view);  // a bad view fails before the run, not after it
  const auto server = attach_lola(session, o.lola, err);
  console::InterruptFlag interrupt;
  const auto t0 = std::chrono::steady_clock::now();
  bool interrupted = false;
  double requested = o.seconds;
  if (!o.debug.address.empty())
    requested = serve_simulation(session, o.debug, out);  // until --seconds or a signal
  else
    interrupted = run_to_end(session, o, server.get(), renderer, recorder, interrupt, err);
  sim::RunTiming timing{.interrupted = interrupted, .requested_time = requested};
  timing.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (server) timing.lola = &server->report();
  write_outcome(sim, o, timing, renderer, recorder, out);
  return interrupted ? 128 + interrupt.signal() : 0;
}

}  // namespace

int run_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "run");
    RunOptions o;
    o.overlay = !a.flag("--no-overlay");  // before positional(), which skips values
    o.scene = a.positional("scene");
    o.seconds =
        console::checked_run_seconds(a.number_or("--seconds", 10.0), "stride run: --seconds");
    if (a.has("--ensemble")) return run_ensemble(a, o.scene, o.seconds, out);
    return run_once(read_run_options(a, std::move(o)), out, err);
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
