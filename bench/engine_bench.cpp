// Both physics engines side by side: the NAO standing and the closed-loop hip-strategy medium walk
// on its uneven floor with its controller, at the shipped settings and the old ones. Counters:
// steps/s (physics steps per CPU second), rtf (simulated seconds per CPU second) and contacts (the
// mean contact points a step). The walk runs with the floor's tiles as the engines build them
// (`floor:engine`: ODE's static grid; MuJoCo's blocks of static bodies, or under the contact law
// no tiles in its model at all, mj_tile_contacts.hpp) and, for what that buys, as 1920 separate
// static boxes (`floor:boxes`).
// `--setting=<label>=<attr=v,...>[@walk scene]` (repeatable) times further settings beside them.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "console/session/sim_session.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/world/physics_world.hpp"

namespace {

struct Setting {
  std::string label;
  std::string physics;  // attributes set over the scene's <physics>
  bool law = true;      // false: without the scene's <contact> law, each engine's own contact
  std::string walk = "scenes/experiments/hip_medium.xml";
};

// The shipped settings under the scene's contact law (ODE's is what the walking scenes state;
// the standing scene states none and runs ODE's default, iterative 10), the faster ones measured
// against them (scenes/experiments/README.md, "fast converged settings"), then the old study
// settings and the artefact every walking scene stated before (ODE iterative 20), without the law.
std::vector<Setting> default_settings() {
  return {
      {"ode exact 1 ms, law (shipped)", "engine=ode,solver=exact"},
      {"mujoco newton 1 ms, law", "engine=mujoco,solver=exact"},
      {"mujoco newton 0.5 ms, law", "engine=mujoco,solver=exact,step=0.5ms"},
      {"mujoco newton 1.25 ms, law", "engine=mujoco,solver=exact,step=1.25ms"},
      {"ode exact 2 ms, law (not converged)", "engine=ode,solver=exact,step=2ms"},
      {"ode iterative 50, law (not converged)", "engine=ode,solver=iterative,iterations=50"},
      {"ode iterative 10 (standing scenes' default)", "engine=ode,solver=iterative,iterations=10"},
      {"ode exact 1 ms (old study setting)", "engine=ode,solver=exact", false},
      {"mujoco newton 0.5 ms (old study setting)", "engine=mujoco,solver=exact,step=0.5ms", false},
      {"mujoco newton 1 ms (old)", "engine=mujoco,solver=exact", false},
      {"ode iterative 20 (old default, artefact)", "engine=ode,solver=iterative,iterations=20",
       false}};
}

stride::sim::SceneDescription load(const std::string& scene, const Setting& s,
                                   bool tiles_as_boxes) {
  auto d = stride::sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/" + scene,
                                         stride::sim::parse_physics_setting(s.physics));
  if (!s.law) d.physics.contact_law.reset();
  if (tiles_as_boxes) {
    for (std::size_t i = 0; i < d.uneven.size(); ++i)
      for (const auto& t :
           stride::sim::uneven_tiles(d.uneven[i], stride::sim::uneven_patch_seed(d, i)))
        d.boxes.push_back(t);
    d.uneven.clear();
  }
  return d;
}

void run(benchmark::State& state, const std::string& scene, double settle, const Setting& setting,
         bool boxes) {
  stride::console::SimSession session(load(scene, setting, boxes));
  auto& sim = session.simulation();
  sim.run_for(settle);
  double contacts = 0;
  for (auto _ : state) {
    sim.step();
    contacts += static_cast<double>(sim.world().contacts().size());
  }
  state.SetLabel(setting.label + (boxes ? ", floor:boxes" : ""));
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["rtf"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * sim.scene().physics.step,
                         benchmark::Counter::kIsRate);
  state.counters["contacts"] = contacts / static_cast<double>(state.iterations());
}

// The standing NAO from 0.5 s. The hip walk from 2.5 s on: the walk has started (2 s of standing
// first) and runs for the whole timing, 10 s of simulated time whatever the step (a fixed count:
// Google Benchmark refuses MinTime beside Iterations, and a count chosen by time would run past
// the 15 s walk's end).
void register_setting(const Setting& s, bool with_boxes) {
  const double step = load(s.walk, s, false).physics.step;
  const auto steps = static_cast<benchmark::IterationCount>(std::llround(10.0 / step));
  benchmark::RegisterBenchmark(("BM_NaoStanding/" + s.label).c_str(), [s](benchmark::State& st) {
    run(st, "scenes/nao_stand.xml", 0.5, s, false);
  })->MinTime(2.0);
  for (bool boxes : {false, true}) {
    if (boxes && !with_boxes) continue;
    benchmark::RegisterBenchmark(
        ("BM_HipWalk/" + s.label + (boxes ? "/floor:boxes" : "")).c_str(),
        [s, boxes](benchmark::State& st) { run(st, s.walk, 2.5, s, boxes); })
        ->Iterations(steps);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<Setting> settings = default_settings();
  std::vector<char*> rest;
  const std::string flag = "--setting=";
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    const auto eq = a.find('=', flag.size());
    if (a.rfind(flag, 0) == 0 && eq != std::string::npos) {
      Setting s{a.substr(flag.size(), eq - flag.size()), a.substr(eq + 1)};
      if (const auto at = s.physics.find('@'); at != std::string::npos) {
        s.walk = s.physics.substr(at + 1);
        s.physics.resize(at);
      }
      settings.push_back(s);
    } else
      rest.push_back(argv[i]);
  }
  for (std::size_t i = 0; i < settings.size(); ++i) register_setting(settings[i], i < 2);
  int n = static_cast<int>(rest.size());
  benchmark::Initialize(&n, rest.data());
  if (benchmark::ReportUnrecognizedArguments(n, rest.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
