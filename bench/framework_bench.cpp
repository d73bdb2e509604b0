// The module framework's own per-frame cost: 30 representations, 27 trivial modules, a null link.
// Target: below 5 us per frame without logging.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <utility>

#include "robot/runtime/runtime.hpp"

namespace stride::bench {

inline constexpr std::array<std::string_view, 26> kNames = {
    "Rep00", "Rep01", "Rep02", "Rep03", "Rep04", "Rep05", "Rep06", "Rep07", "Rep08",
    "Rep09", "Rep10", "Rep11", "Rep12", "Rep13", "Rep14", "Rep15", "Rep16", "Rep17",
    "Rep18", "Rep19", "Rep20", "Rep21", "Rep22", "Rep23", "Rep24", "Rep25"};

template <int N>
struct Rep {
  STRIDE_FIELDS(Rep);
  STRIDE_FIELD(double, x) = 0;
  STRIDE_FIELD((std::array<double, 6>), pad){};
  static constexpr std::string_view kTypeName = kNames[N];
};

// Rep<N> = Rep<N-1> + 1; Rep<0> from FrameInfo.
template <int N>
class Chain final : public Module {
 public:
  explicit Chain(ModuleContext& c) : out_(c.provide<Rep<N>>()) {
    if constexpr (N == 0)
      frame_ = &c.require<FrameInfo>();
    else
      in_ = &c.require<Rep<N - 1>>();
  }
  void update() override {
    if constexpr (N == 0)
      out_.x = static_cast<double>(frame_->frame);
    else
      out_.x = in_->x + 1;
  }

 private:
  const FrameInfo* frame_ = nullptr;
  const Rep<N - (N > 0)>* in_ = nullptr;
  Rep<N>& out_;
};

class Sink final : public Module {
 public:
  explicit Sink(ModuleContext& c)
      : in_(c.require<Rep<25>>()), out_(c.provide<hal::ActuatorFrame>()) {}
  void update() override { out_.position[0] = in_.x; }

 private:
  const Rep<25>& in_;
  hal::ActuatorFrame& out_;
};

class NullLink final : public hal::HardwareLink {
 public:
  bool read(hal::SensorFrame& s) override {
    s.time += 0.01;
    return true;
  }
  void write(const hal::ActuatorFrame&) override {}
  double period() const override { return 0.01; }
  std::string name() const override { return "null"; }
};

template <std::size_t... N>
void register_chain(ModuleRegistry& r, std::index_sequence<N...>) {
  (r.add<Chain<N>>("Chain" + std::to_string(N)), ...);
}

ModuleRegistry bench_registry() {
  ModuleRegistry r;
  register_chain(r, std::make_index_sequence<26>());
  r.add<Sink>("Sink");
  return r;
}

void BM_FrameOverhead(benchmark::State& state) {
  const auto registry = bench_registry();
  NullLink link;
  Runtime rt(registry, {}, link);
  if (rt.representation_names().size() != 30) state.SkipWithError("expected 30 representations");
  for (auto _ : state) rt.step();
  state.counters["modules"] = static_cast<double>(rt.module_order().size());
  state.counters["representations"] = static_cast<double>(rt.representation_names().size());
}
BENCHMARK(BM_FrameOverhead);

// The same frame while logging every representation to a file (flushed each frame).
void BM_FrameWithLog(benchmark::State& state) {
  const auto registry = bench_registry();
  NullLink link;
  Runtime rt(registry, {}, link);
  const auto path =
      (std::filesystem::temp_directory_path() / "stride_framework_bench.log").string();
  rt.start_log(path);
  for (auto _ : state) rt.step();
  rt.stop_log();
  state.counters["bytes_per_frame"] = static_cast<double>(std::filesystem::file_size(path)) /
                                      static_cast<double>(state.iterations());
  std::filesystem::remove(path);
}
BENCHMARK(BM_FrameWithLog);

}  // namespace stride::bench

BENCHMARK_MAIN();
