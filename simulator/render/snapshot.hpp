#pragma once
// One picture of a simulation, and a video as numbered pictures taken every few frames.
#include <cstdint>
#include <string>

#include "simulator/render/world_renderer.hpp"

namespace stride::sim {
class Simulation;
}

namespace stride::render {

// Renders `view` (built-in views frame robot `robot`) of the simulation into a PNG; throws
// stride::Error and writes nothing on error.
void write_snapshot(WorldRenderer& renderer, const sim::Simulation& sim, const std::string& path,
                    const std::string& view, int robot = 0);

// Writes <dir>/frame_000000.png, ... every `every_steps` physics steps while recording.
class VideoRecorder {
 public:
  // Checks the view and creates `dir`; throws stride::Error on either.
  void start(const sim::Simulation& sim, const std::string& dir, const std::string& view,
             std::uint64_t every_steps, int robot = 0);
  void stop() { active_ = false; }
  bool active() const { return active_; }
  std::uint64_t frames() const { return frames_; }
  // Called after every physics step; renders when the step count is due.
  void after_step(WorldRenderer& renderer, const sim::Simulation& sim);

 private:
  bool active_ = false;
  std::string dir_, view_;
  std::uint64_t every_ = 1, frames_ = 0;
  int robot_ = 0;
};

}  // namespace stride::render
