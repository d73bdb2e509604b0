// Physics throughput: the NAO standing scene at 1 kHz on one core, per solver setting.
// Counters: steps/s (physics steps per CPU second) and rtf (simulated seconds per CPU second).
#include <benchmark/benchmark.h>

#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"

namespace {

stride::sim::SceneDescription stand_scene(bool exact, int iterations) {
  auto s = stride::sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/scenes/nao_stand.xml");
  s.physics.solver = exact ? stride::sim::PhysicsSettings::Solver::Exact
                           : stride::sim::PhysicsSettings::Solver::Iterative;
  s.physics.iterations = iterations;
  return s;
}

void run(benchmark::State& state, bool exact, int iterations) {
  stride::sim::Simulation sim(stand_scene(exact, iterations));
  sim.run_for(0.5);  // settled contacts
  for (auto _ : state) sim.step();
  state.counters["steps/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["rtf"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * sim.scene().physics.step,
                         benchmark::Counter::kIsRate);
}

void BM_NaoStandingIterative(benchmark::State& state) {
  run(state, false, static_cast<int>(state.range(0)));
}
// 1 iteration shows the per-step cost outside the solver iterations.
BENCHMARK(BM_NaoStandingIterative)->Arg(1)->Arg(10)->Arg(20)->Arg(50)->MinTime(2.0);

// Standing on the thesis' uneven floor (4 m x 1.2 m of 5 cm tiles: 1920 static boxes), default
// solver: the static broad phase keeps this near the flat-ground figure.
void BM_NaoStandingOnUnevenFloor(benchmark::State& state) {
  auto scene = stand_scene(false, 20);
  stride::sim::UnevenPatch patch;
  patch.centre = Eigen::Vector2d(1.9, 0);  // the robot stands on the first tiles
  patch.size = Eigen::Vector2d(4, 1.2);
  patch.seed = 7;
  scene.uneven.push_back(patch);
  stride::sim::Simulation sim(scene);
  sim.run_for(0.5);
  for (auto _ : state) sim.step();
  state.counters["rtf"] =
      benchmark::Counter(static_cast<double>(state.iterations()) * sim.scene().physics.step,
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NaoStandingOnUnevenFloor)->MinTime(2.0);

void BM_NaoStandingExact(benchmark::State& state) {
  run(state, true, 0);
}
BENCHMARK(BM_NaoStandingExact)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
