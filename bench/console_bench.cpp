// Console commands on a paused simulation must answer within 1 ms (issue 5): get, set, help,
// mr ?, expect, and the bare parser.
#include <benchmark/benchmark.h>

#include <sstream>

#include "console/interpreter/command_parser.hpp"
#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"

namespace {

using stride::console::Interpreter;
using stride::console::LocalTarget;

struct PausedConsole {
  PausedConsole()
      : target(STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml"), console(target, out) {
    console.execute("run 0.2");
  }
  LocalTarget target;
  std::ostringstream out;
  Interpreter console;
};

PausedConsole& paused() {
  static PausedConsole c;  // one scene for every benchmark: loading it is not what is measured
  return c;
}

void run_command(benchmark::State& state, const char* line) {
  auto& c = paused();
  for (auto _ : state) {
    c.out.str("");
    c.console.execute(line);
    benchmark::DoNotOptimize(c.out.str().size());
  }
}

void BM_GetJointRequest(benchmark::State& s) {
  run_command(s, "get representation:JointRequest");
}
void BM_GetOneField(benchmark::State& s) {
  run_command(s, "get representation:JointRequest.position[10]");
}
void BM_SetStandParameters(benchmark::State& s) {
  run_command(s, "set module:Stand knee_pitch=0.6 hip_pitch=-0.3");
}
void BM_Help(benchmark::State& s) {
  run_command(s, "help");
}
void BM_ModuleRequestList(benchmark::State& s) {
  run_command(s, "mr ?");
}
void BM_ExpectTorsoHeight(benchmark::State& s) {
  run_command(s, "expect robot.torso.z > 0.1");
}
void BM_TypeDescription(benchmark::State& s) {
  run_command(s, "get module:Stand ?");
}
void BM_ParseOnly(benchmark::State& s) {
  for (auto _ : s)
    benchmark::DoNotOptimize(stride::console::parse_command(
        "expect representation:JointRequest.position[10] ~= 0.6 1e-3"));
}

BENCHMARK(BM_GetJointRequest)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GetOneField)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SetStandParameters)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Help)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ModuleRequestList)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ExpectTorsoHeight)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_TypeDescription)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ParseOnly)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
