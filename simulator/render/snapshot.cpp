#include "simulator/render/snapshot.hpp"

#include <cstdio>
#include <filesystem>

#include "robot/core/error.hpp"
#include "simulator/render/png_file.hpp"
#include "simulator/render/views.hpp"
#include "simulator/simulation.hpp"

namespace stride::render {

void write_snapshot(WorldRenderer& renderer, const sim::Simulation& sim, const std::string& path,
                    const std::string& view, int robot) {
  const CameraView camera = resolve_view(sim, view, robot);
  const RgbaImage image = renderer.render(sim.world(), camera, sim.scene().lights);
  write_png(path, image);
}

void VideoRecorder::start(const sim::Simulation& sim, const std::string& dir,
                          const std::string& view, std::uint64_t every_steps, int robot) {
  if (every_steps == 0) throw Error("video: expected a frame interval of at least one step");
  resolve_view(sim, view, robot);  // fail now, not at the first frame
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw Error("video: cannot create directory '" + dir + "'");
  dir_ = dir;
  view_ = view;
  every_ = every_steps;
  robot_ = robot;
  frames_ = 0;
  active_ = true;
}

void VideoRecorder::after_step(WorldRenderer& renderer, const sim::Simulation& sim) {
  if (!active_ || sim.steps() % every_ != 0) return;
  char name[32];
  std::snprintf(name, sizeof name, "frame_%06llu.png", static_cast<unsigned long long>(frames_));
  try {
    write_snapshot(renderer, sim, (std::filesystem::path(dir_) / name).string(), view_, robot_);
  } catch (...) {
    active_ = false;  // one error, not one per step
    throw;
  }
  ++frames_;
}

}  // namespace stride::render
