// The debug server's loop side makes no heap allocation at a frame boundary once a subscription
// streams (a control loop must not stall in the allocator): a walking NAO served to a client that
// watches what a live view watches (20 joint positions, the IMU angles, every joint position and
// the module times), every allocation of the loop thread counted while the boundary runs. This
// binary replaces the allocator's entry points (tests/allocation/allocation_counter.hpp), so it is
// kept apart from the other debug tests.
#include <gtest/gtest.h>

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "console/session/sim_session.hpp"
#include "robot/debug/debug_client.hpp"
#include "robot/debug/server.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/allocation/allocation_counter.hpp"

namespace stride {
namespace {

using allocation_counter::allocations;
using allocation_counter::counting;

// Counts the loop thread's allocations while the debug server's boundary runs.
class CountingBoundary final : public FrameBoundary {
 public:
  explicit CountingBoundary(FrameBoundary& inner) : inner_(inner) {}
  void after_frame(Runtime& rt) override {
    const long before = allocations;
    counting = true;
    inner_.after_frame(rt);
    counting = false;
    last = allocations - before;
  }
  void detached(Runtime& rt) override { inner_.detached(rt); }
  long last = 0;

 private:
  FrameBoundary& inner_;
};

// The keys of tests/debug/view_peer.py's page and of the view's kinematic robot.
std::vector<std::string> view_keys() {
  std::vector<std::string> keys;
  for (const char* rep : {"JointRequest", "JointSensorData"})
    for (int i = 0; i < 10; ++i)
      keys.push_back("representation:" + std::string(rep) + ".position[" + std::to_string(i) + "]");
  keys.insert(keys.end(), {"representation:JointSensorData.position",
                           "representation:InertialSensorData.angles",
                           "representation:ModuleTimes.modules", "representation:ModuleTimes.ns"});
  return keys;
}

TEST(LoopSideAllocation, NoneAtAFrameBoundaryWhileASubscriptionStreams) {
  console::SimSession session(
      sim::parse_scene_file(STRIDE_SOURCE_DIR "/scenes/experiments/hip_medium.xml"));
  Runtime& rt = *session.runtime(0);
  debug::ServerOptions options;
  options.listen = {"127.0.0.1", 0};
  options.robot = "nao";
  options.log = [](const std::string&) {};
  debug::DebugServer server(options);
  CountingBoundary boundary(server.boundary());
  rt.set_frame_boundary(&boundary);
  auto& sim = session.simulation();
  const double period = sim.robot(0).period();
  auto run = [&](double seconds, long& allocated, int& frames) {
    const std::int64_t first = rt.representation<FrameInfo>().frame;
    std::int64_t seen = first;
    for (const double end = sim.time() + seconds; sim.time() < end - 1e-9;) {
      sim.step();
      if (rt.representation<FrameInfo>().frame == seen) continue;  // no control frame this step
      seen = rt.representation<FrameInfo>().frame;
      allocated += boundary.last;
      ++frames;
      std::this_thread::sleep_for(std::chrono::milliseconds(2));  // the server thread keeps up
    }
  };

  debug::DebugClient client(server.endpoint(), "");
  std::atomic<bool> subscribed{false};
  std::thread subscribe([&] {  // answered from a frame's snapshot: frames run meanwhile
    debug::Request r;
    r.op = debug::Op::Subscribe;
    r.keys = view_keys();
    r.every = 1;
    client.call(r);
    subscribed = true;
  });
  long warm_allocated = 0;
  int warm_frames = 0;
  for (int i = 0; i < 2000 && !subscribed; ++i) run(period, warm_allocated, warm_frames);
  subscribe.join();
  ASSERT_TRUE(subscribed);
  std::atomic<bool> stop{false};
  std::atomic<long> samples{0};
  std::thread reader([&] {
    while (!stop)
      if (client.next_sample(0.01)) ++samples;
  });
  run(1.0, warm_allocated, warm_frames);  // the snapshot buffers in flight are made
  // A slow build (sanitizers) keeps more buffers in flight: warm up until the pool stops growing.
  for (int i = 0; i < 20; ++i) {
    const std::uint64_t grown = server.stats().loop_allocations;
    run(0.5, warm_allocated, warm_frames);
    if (server.stats().loop_allocations == grown) break;
  }

  long allocated = 0;
  int frames = 0;
  const std::uint64_t grown_before = server.stats().loop_allocations;
  run(2.0, allocated, frames);
  stop = true;
  reader.join();
  rt.set_frame_boundary(nullptr);

  EXPECT_GT(warm_allocated, 0);  // the counter sees the loop side's first buffers
  EXPECT_GE(frames, static_cast<int>(2.0 / period) - 1);
  EXPECT_GT(samples.load(), frames / 2);  // the subscription streamed meanwhile
  // A lagging server thread (a loaded or sanitized machine) makes the pool grow now and then, a
  // few allocations each time; a per-frame allocation would count at least one a frame.
  const std::uint64_t grown = server.stats().loop_allocations - grown_before;
  EXPECT_LE(allocated, static_cast<long>(frames / 4)) << "over " << frames << " frames";
  EXPECT_LE(grown, static_cast<std::uint64_t>(frames / 8));
}

}  // namespace
}  // namespace stride
