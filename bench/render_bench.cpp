// Offscreen rendering: one 640x480 picture of the standing NAO (what a video frame costs).
#include <benchmark/benchmark.h>

#include "simulator/render/views.hpp"
#include "simulator/render/world_renderer.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"

namespace {

void BM_RenderNaoFollowView(benchmark::State& state) {
  stride::sim::Simulation sim(
      stride::sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/scenes/nao_stand.xml"));
  const auto view = stride::render::resolve_view(sim, "follow");
  stride::render::WorldRenderer renderer;
  for (auto _ : state) benchmark::DoNotOptimize(renderer.render(sim.world(), view, {}).rgba.data());
}
BENCHMARK(BM_RenderNaoFollowView)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
