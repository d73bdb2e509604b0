// Physics throughput: the NAO standing scene at 1 kHz on one core, per solver setting.
// Counters: steps/s (physics steps per CPU second) and rtf (simulated seconds per CPU second).
#include <benchmark/benchmark.h>

#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"

namespace {

stride::sim::SceneDescription stand_scene() {
  return stride::sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/scenes/nao_stand.xml");
}

stride::sim::SceneDescription stand_scene(bool exact, int iterations) {
  auto s = stand_scene();
  s.physics.solver = exact ? stride::sim::PhysicsSettings::Solver::Exact
                           : stride::sim::PhysicsSettings::Solver::Iterative;
  s.physics.iterations = iterations;
  return s;
}

void run(benchmark::State& state, stride::sim::SceneDescription scene) {
  stride::sim::Simulation sim(std::move(scene));
  sim.run_for(0.5);  // settled contacts
  for (auto _ : state) sim.step();
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["rtf"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * sim.scene().physics.step,
                         benchmark::Counter::kIsRate);
}

// The scene as written: the default solver setting (iterative, 10 iterations).
void BM_NaoStandingDefault(benchmark::State& state) {
  run(state, stand_scene());
}
BENCHMARK(BM_NaoStandingDefault)->MinTime(2.0);

void BM_NaoStandingIterative(benchmark::State& state) {
  run(state, stand_scene(false, static_cast<int>(state.range(0))));
}
// 1 iteration shows the per-step cost outside the solver iterations; 20 is what the walking
// studies state.
BENCHMARK(BM_NaoStandingIterative)->Arg(1)->Arg(10)->Arg(20)->Arg(50)->MinTime(2.0);

// Standing on the thesis' uneven floor (4 m x 1.2 m of 5 cm tiles: 1920 static boxes), with the
// walking studies' 20 iterations: the static broad phase keeps this near the flat-ground figure.
void BM_NaoStandingOnUnevenFloor(benchmark::State& state) {
  auto scene = stand_scene(false, 20);
  stride::sim::UnevenPatch patch;
  patch.centre = Eigen::Vector2d(1.9, 0);  // the robot stands on the first tiles
  patch.size = Eigen::Vector2d(4, 1.2);
  patch.seed = 7;
  scene.uneven.push_back(patch);
  run(state, std::move(scene));
}
BENCHMARK(BM_NaoStandingOnUnevenFloor)->MinTime(2.0);

void BM_NaoStandingExact(benchmark::State& state) {
  run(state, stand_scene(true, 0));
}
BENCHMARK(BM_NaoStandingExact)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
