// Both physics engines side by side at their study settings (scenes/experiments/README.md,
// "engines"): the NAO standing and the closed-loop hip-strategy medium walk with its controller.
// Counters: steps/s (physics steps per CPU second) and rtf (simulated seconds per CPU second).
#include <benchmark/benchmark.h>

#include "console/session/sim_session.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace {

// ODE's study setting is the exact solver at 1 ms; MuJoCo's its Newton solver at 0.5 ms (and, for
// the cost of the halved step, Newton at 1 ms).
const char* kSetting[] = {"engine=ode,solver=exact", "engine=mujoco,solver=exact,step=0.5ms",
                          "engine=mujoco,solver=exact"};
const char* kLabel[] = {"ode exact 1 ms", "mujoco newton 0.5 ms", "mujoco newton 1 ms"};

void run(benchmark::State& state, const char* scene, double settle) {
  const std::string path = std::string(STRIDE_SOURCE_DIR) + "/" + scene;
  stride::console::SimSession session(stride::sim::parse_scene_file(
      path, stride::sim::parse_physics_setting(kSetting[state.range(0)])));
  auto& sim = session.simulation();
  sim.run_for(settle);
  for (auto _ : state) sim.step();
  state.SetLabel(kLabel[state.range(0)]);
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["rtf"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * sim.scene().physics.step,
                         benchmark::Counter::kIsRate);
}

void BM_NaoStanding(benchmark::State& state) {
  run(state, "scenes/nao_stand.xml", 0.5);
}
BENCHMARK(BM_NaoStanding)->Arg(0)->Arg(1)->Arg(2)->MinTime(2.0);

// From 2.5 s on: the walk has started (2 s of standing first) and runs for the whole timing,
// 10 s of it at 1 ms, 5 s at 0.5 ms (a fixed count: Google Benchmark refuses MinTime beside
// Iterations, and a count chosen by time would run past the 15 s walk's end on a fast host).
void BM_HipWalk(benchmark::State& state) {
  run(state, "scenes/experiments/hip_medium.xml", 2.5);
}
BENCHMARK(BM_HipWalk)->Arg(0)->Arg(1)->Arg(2)->Iterations(10000);

}  // namespace

BENCHMARK_MAIN();
