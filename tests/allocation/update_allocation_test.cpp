// No shipped module allocates in update() once running (a robot's control loop must not stall in
// the allocator or throw std::bad_alloc): every allocation during Runtime::step() is counted while
// the controllers of the shipped robot configs walk and stand the simulated NAO. This test binary
// replaces the global operator new for that, so it is kept apart from the others.
#include <cstdlib>
#include <new>

#include <gtest/gtest.h>

#include "console/session/sim_session.hpp"
#include "robot/app/robot_config.hpp"
#include "simulator/scene/scene_parser.hpp"

namespace {
// Test-only counter: operator new has nowhere else to report to.
thread_local bool counting = false;
thread_local long allocations = 0;
}  // namespace

void* operator new(std::size_t n) {
  if (counting) ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  return ::operator new(n);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace stride {
namespace {

// Runs `config`'s controller on `scene`'s robot for `seconds`, counting allocations in step()
// after the first `warm_up` seconds (first frames may size buffers).
long allocations_while_running(const std::string& scene_file, const std::string& config_file,
                               double warm_up, double seconds) {
  sim::SceneDescription scene = sim::parse_scene_file(scene_file);
  scene.robots[0].controller = parse_robot_config_file(config_file).controller;
  scene.robots[0].period = 0.012;
  console::SimSession session(std::move(scene));
  auto& sim = session.simulation();
  Runtime* rt = session.runtime(0);
  sim.set_controller(0, [&](sim::SimulatedRobot&) {
    counting = sim.time() > warm_up;
    rt->step();
    counting = false;
  });
  allocations = 0;
  sim.run_for(seconds);
  return allocations;
}

TEST(UpdateAllocation, HipWalkControllerAllocatesNothingPerFrame) {
  EXPECT_EQ(allocations_while_running(STRIDE_SOURCE_DIR "/scenes/experiments/hip_medium.xml",
                                      STRIDE_SOURCE_DIR "/scenes/robots/nao/config/hip_walk.xml",
                                      0.1, 4.0),
            0);
}

TEST(UpdateAllocation, StandControllerAllocatesNothingPerFrame) {
  EXPECT_EQ(allocations_while_running(STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml",
                                      STRIDE_SOURCE_DIR "/scenes/robots/nao/config/stand.xml", 0.1,
                                      1.0),
            0);
}

TEST(UpdateAllocation, TheCounterSeesAnAllocation) {
  allocations = 0;
  counting = true;
  void* p = ::operator new(16);  // a call, which unlike a new-expression is never elided
  counting = false;
  ::operator delete(p);
  EXPECT_EQ(allocations, 1);
}

}  // namespace
}  // namespace stride
