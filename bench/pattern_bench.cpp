// Generating the Table 4.3 walk (60 steps, 15 s) at the 100 Hz control rate; target < 1 ms.
#include <benchmark/benchmark.h>

#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"

namespace {

using namespace stride::walking;

void BM_Pattern15s(benchmark::State& state) {
  const PatternParameters p = preset("medium");
  for (auto _ : state) {
    const StretchedKneePattern w(p);
    const auto walk = sample_walk(w, 0.01);
    benchmark::DoNotOptimize(walk.back().zmp);
  }
}
BENCHMARK(BM_Pattern15s)->Unit(benchmark::kMicrosecond);

void BM_PatternWithIk15s(benchmark::State& state) {
  const PatternParameters p = preset("medium");
  for (auto _ : state) {
    const StretchedKneePattern w(p);
    double knee = 0.0;
    for (const PatternSample& s : sample_walk(w, 0.01)) knee += leg_joints(s).left[3];
    benchmark::DoNotOptimize(knee);
  }
}
BENCHMARK(BM_PatternWithIk15s)->Unit(benchmark::kMicrosecond);

void BM_OneSampleWithIk(benchmark::State& state) {
  const StretchedKneePattern w(preset("medium"));
  double t = 0.0;
  for (auto _ : state) {
    t = t > 15.0 ? 0.0 : t + 0.01;
    benchmark::DoNotOptimize(leg_joints(w.sample(t)));
  }
}
BENCHMARK(BM_OneSampleWithIk)->Unit(benchmark::kNanosecond);

}  // namespace

BENCHMARK_MAIN();
