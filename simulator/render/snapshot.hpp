#pragma once
// One picture of a simulation, and a video: a movie (animated PNG or MP4), numbered PNG pictures,
// or both, taken every few physics steps. Pictures carry the time and a status line unless asked
// not to.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "simulator/render/world_renderer.hpp"

namespace stride::sim {
class Simulation;
}

namespace stride::render {

class MovieFile;

// "t 12.34 s" and a status line of robot `robot` (torso height, pitch, roll, steps, fell).
std::vector<std::string> status_lines(const sim::Simulation& sim, int robot);

// Renders `view` (built-in views frame robot `robot`) of the simulation, with the status lines
// drawn over it when `overlay`.
RgbaImage render_view(WorldRenderer& renderer, const sim::Simulation& sim, const std::string& view,
                      int robot = 0, bool overlay = true);

// Renders into a PNG; throws stride::Error and writes nothing on error.
void write_snapshot(WorldRenderer& renderer, const sim::Simulation& sim, const std::string& path,
                    const std::string& view, int robot = 0, bool overlay = true);

class VideoRecorder {
 public:
  VideoRecorder();
  ~VideoRecorder();
  // Starts recording into each destination: a movie file (*.apng, *.mp4: movie_file.hpp) or a
  // folder of frame_000000.png, ... (created if missing; its parent must exist). Checks the view
  // first; throws stride::Error and records nothing on any error.
  void start(const sim::Simulation& sim, const std::vector<std::string>& destinations,
             const std::string& view, std::uint64_t every_steps, int robot = 0,
             bool overlay = true);
  // Ends the recording; a movie is finished and moved into place (throws if that fails).
  void stop();
  bool active() const { return active_; }
  std::uint64_t frames() const { return frames_; }
  // Called after every physics step; renders when the step count is due.
  void after_step(WorldRenderer& renderer, const sim::Simulation& sim);

 private:
  bool active_ = false;
  std::string frames_dir_, view_;
  std::unique_ptr<MovieFile> movie_;
  std::uint64_t every_ = 1, frames_ = 0;
  int robot_ = 0;
  bool overlay_ = true;
};

}  // namespace stride::render
