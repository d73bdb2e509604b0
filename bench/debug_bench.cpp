// The debug server's costs (robot/debug/): a `get` round trip over loopback TCP while the robot
// loop runs (target: median below 200 us), and what streaming 50 fields every frame costs the
// control loop at its frame boundary (target: below 5 us per frame), against the same boundary
// with a connected client that streams nothing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include "behaviours/stand/stand.hpp"
#include "robot/debug/debug_client.hpp"
#include "robot/debug/server.hpp"
#include "robot/runtime/nao_io_modules.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride::bench {
namespace {

// Sensor frames that change every frame, as a robot's do.
class MovingLink final : public hal::HardwareLink {
 public:
  bool read(hal::SensorFrame& s) override {
    s.time = n_ * 0.012;
    for (int i = 0; i < hal::kNumJoints; ++i) s.position[i] = 0.1 * std::sin(0.3 * i + 0.01 * n_);
    s.accelerometer = {0.1, -0.2, 9.81};
    s.fsr.fill(5.0);
    ++n_;
    return true;
  }
  void write(const hal::ActuatorFrame&) override {}
  double period() const override { return 0.012; }
  std::string name() const override { return "moving"; }

 private:
  std::int64_t n_ = 0;
};

struct Robot {
  Robot() : runtime(registry(), config(), link) {}
  static ModuleRegistry registry() {
    ModuleRegistry r;
    register_nao_io_modules(r);
    behaviours::register_stand(r);
    return r;
  }
  static RuntimeConfig config() {
    RuntimeConfig c;
    c.providers = {{"JointRequest", "Stand"}};
    return c;
  }
  MovingLink link;
  Runtime runtime;
};

debug::ServerOptions loopback() {
  debug::ServerOptions o;
  o.listen = {"127.0.0.1", 0};
  o.robot = "bench";
  o.log = [](const std::string&) {};
  o.request_rate = 1e9;  // a benchmark asks as fast as it can; the limit is a test's business
  return o;
}

debug::Request request(debug::Op op, std::string key = {}) {
  debug::Request r;
  r.op = op;
  r.key = std::move(key);
  return r;
}

// 50 fields: JointRequest and JointSensorData positions (25 each).
std::vector<std::string> fifty_fields() {
  std::vector<std::string> keys;
  for (const char* rep : {"JointRequest", "JointSensorData"})
    for (int i = 0; i < 25; ++i)
      keys.push_back("representation:" + std::string(rep) + ".position[" + std::to_string(i) + "]");
  return keys;
}

void BM_GetRoundTrip(benchmark::State& state) {
  Robot robot;
  debug::DebugServer server(loopback());
  robot.runtime.set_frame_boundary(&server.boundary());
  std::atomic<bool> stop{false};
  std::thread loop([&] {  // a 12 ms robot loop, as on the NAO
    auto due = std::chrono::steady_clock::now();
    while (!stop) {
      robot.runtime.step();
      due += std::chrono::milliseconds(12);
      std::this_thread::sleep_until(due);
    }
  });
  debug::DebugClient client(server.endpoint(), "");
  for (auto _ : state) {
    auto reply = client.call(debug::request(debug::Op::Get, "module:Stand"));
    benchmark::DoNotOptimize(reply.get());
  }
  stop = true;
  loop.join();
  robot.runtime.set_frame_boundary(nullptr);
}
BENCHMARK(BM_GetRoundTrip)->Unit(benchmark::kMicrosecond)->UseRealTime();

// The frame boundary alone, timed by hand: the modules run outside the timed part, and the
// frames are 1 ms apart so the server thread keeps up as it does at 12 ms.
void boundary_cost(benchmark::State& state, const std::vector<std::string>& keys) {
  Robot robot;
  debug::DebugServer server(loopback());
  debug::DebugClient client(server.endpoint(), "");
  if (!keys.empty()) {  // the subscription is answered from a frame's snapshot: frames run
                        // meanwhile
    std::atomic<bool> subscribed{false};
    std::thread subscribe([&] {
      debug::Request r = debug::request(debug::Op::Subscribe);
      r.keys = keys;
      client.call(r);
      subscribed = true;
    });
    while (!subscribed) {
      robot.runtime.step();
      server.boundary().after_frame(robot.runtime);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    subscribe.join();
  }
  std::atomic<bool> stop{false};
  std::thread reader([&] {
    while (!stop) client.next_sample(0.01);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the wanted mask arrives
  std::vector<double> us;
  for (auto _ : state) {
    robot.runtime.step();
    const auto t0 = std::chrono::steady_clock::now();
    server.boundary().after_frame(robot.runtime);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    state.SetIterationTime(s);
    us.push_back(s * 1e6);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  stop = true;
  reader.join();
  std::sort(us.begin(), us.end());  // the tail is what a real-time loop feels
  state.counters["p50_us"] = us[us.size() / 2];
  state.counters["p99_us"] = us[us.size() * 99 / 100];
  state.counters["samples_sent"] = static_cast<double>(server.stats().samples_sent);
  state.counters["snapshots_lost"] = static_cast<double>(server.stats().snapshots_lost);
}

void BM_FrameBoundaryNoStream(benchmark::State& state) {
  boundary_cost(state, {});
}
BENCHMARK(BM_FrameBoundaryNoStream)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(2000);

void BM_FrameBoundaryStreaming50Fields(benchmark::State& state) {
  boundary_cost(state, fifty_fields());
}
BENCHMARK(BM_FrameBoundaryStreaming50Fields)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(2000);

// What `stride view --connect` streams to draw a robot: its joints, IMU angles and module times,
// beside the page's plots (here 10 joint requests).
std::vector<std::string> view_fields() {
  std::vector<std::string> keys = {
      "representation:JointSensorData.position", "representation:InertialSensorData.angles",
      "representation:ModuleTimes.modules", "representation:ModuleTimes.ns",
      "representation:FrameInfo.time"};
  for (int i = 0; i < 10; ++i)
    keys.push_back("representation:JointRequest.position[" + std::to_string(i) + "]");
  return keys;
}

void BM_FrameBoundaryViewFields(benchmark::State& state) {
  boundary_cost(state, view_fields());
}
BENCHMARK(BM_FrameBoundaryViewFields)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond)
    ->Iterations(2000);

}  // namespace
}  // namespace stride::bench

BENCHMARK_MAIN();
