// Both physics engines side by side: the NAO standing and the closed-loop hip-strategy medium walk
// on its uneven floor with its controller. Counters: steps/s (physics steps per CPU second) and
// rtf (simulated seconds per CPU second). The walk runs with the floor's tiles as the engines
// build them (`floor:engine`: MuJoCo's blocks of static bodies, ODE's static grid) and, for what
// that buys, as 1920 separate static boxes (`floor:boxes`, how MuJoCo held them before).
#include <benchmark/benchmark.h>

#include "console/session/sim_session.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/world/physics_world.hpp"

namespace {

// The old study settings (ODE's exact solver at 1 ms, MuJoCo's Newton at 0.5 ms and 1 ms) and the
// artefact every walking scene stated before (ODE iterative, 20 iterations).
const char* kSetting[] = {"engine=ode,solver=exact", "engine=mujoco,solver=exact,step=0.5ms",
                          "engine=mujoco,solver=exact", "engine=ode,iterations=20"};
const char* kLabel[] = {"ode exact 1 ms", "mujoco newton 0.5 ms", "mujoco newton 1 ms",
                        "ode iterative 20 (old default)"};

stride::sim::SceneDescription load(const char* scene, int setting, bool tiles_as_boxes) {
  auto d = stride::sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/" + scene,
                                         stride::sim::parse_physics_setting(kSetting[setting]));
  if (tiles_as_boxes) {
    for (std::size_t i = 0; i < d.uneven.size(); ++i)
      for (const auto& t :
           stride::sim::uneven_tiles(d.uneven[i], stride::sim::uneven_patch_seed(d, i)))
        d.boxes.push_back(t);
    d.uneven.clear();
  }
  return d;
}

void run(benchmark::State& state, const char* scene, double settle) {
  const bool boxes = state.range(1) != 0;
  stride::console::SimSession session(load(scene, static_cast<int>(state.range(0)), boxes));
  auto& sim = session.simulation();
  sim.run_for(settle);
  for (auto _ : state) sim.step();
  state.SetLabel(std::string(kLabel[state.range(0)]) + (boxes ? ", floor:boxes" : ""));
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["rtf"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * sim.scene().physics.step,
                         benchmark::Counter::kIsRate);
}

void BM_NaoStanding(benchmark::State& state) {
  run(state, "scenes/nao_stand.xml", 0.5);
}
BENCHMARK(BM_NaoStanding)->Args({0, 0})->Args({1, 0})->Args({2, 0})->MinTime(2.0);

// From 2.5 s on: the walk has started (2 s of standing first) and runs for the whole timing,
// 10 s of it at 1 ms, 5 s at 0.5 ms (a fixed count: Google Benchmark refuses MinTime beside
// Iterations, and a count chosen by time would run past the 15 s walk's end on a fast host).
void BM_HipWalk(benchmark::State& state) {
  run(state, "scenes/experiments/hip_medium.xml", 2.5);
}
BENCHMARK(BM_HipWalk)->ArgsProduct({{0, 1, 2, 3}, {0, 1}})->Iterations(10000);

}  // namespace

BENCHMARK_MAIN();
