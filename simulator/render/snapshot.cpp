#include "simulator/render/snapshot.hpp"

#include <cstdio>
#include <filesystem>

#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"
#include "simulator/render/movie_file.hpp"
#include "simulator/render/png_file.hpp"
#include "simulator/render/text_overlay.hpp"
#include "simulator/render/views.hpp"
#include "simulator/simulation.hpp"

namespace stride::render {
namespace {

std::string fixed(double v, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%+.*f", decimals, v);
  return text;
}

// A folder for frames: the one named, never its parents.
void make_frames_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(dir, ec)) return;
  const fs::path parent = fs::path(dir).lexically_normal().parent_path();
  if (!parent.empty() && !fs::is_directory(parent, ec))
    throw Error("video: cannot create folder " + quote(dir) + ": " + quote(parent.string()) +
                " does not exist");
  if (!fs::create_directory(dir, ec) || ec)
    throw Error("video: cannot create folder " + quote(dir));
}

}  // namespace

std::vector<std::string> status_lines(const sim::Simulation& sim, int robot) {
  char time[32];
  std::snprintf(time, sizeof time, "t %.2f s", sim.time());
  std::vector<std::string> lines{time};
  if (robot < 0 || robot >= sim.robot_count()) return lines;
  const auto& r = sim.robot(robot);
  const sim::TorsoPose p = r.torso_pose();
  const int steps = sim.walk_metrics(robot).result().steps;
  std::string status = r.name() + ": z " + fixed(p.z, 3).substr(1) + " m  pitch " +
                       fixed(p.pitch, 2) + "  roll " + fixed(p.roll, 2) + " rad";
  if (steps > 0) status += "  steps " + std::to_string(steps);
  if (r.fallen()) status += "  FELL";
  lines.push_back(status);
  return lines;
}

RgbaImage render_view(WorldRenderer& renderer, const sim::Simulation& sim, const std::string& view,
                      int robot, bool overlay) {
  const CameraView camera = resolve_view(sim, view, robot);
  RgbaImage image = renderer.render(sim.world(), camera, sim.scene().lights);
  if (overlay) draw_overlay(image, status_lines(sim, robot));
  return image;
}

void write_snapshot(WorldRenderer& renderer, const sim::Simulation& sim, const std::string& path,
                    const std::string& view, int robot, bool overlay) {
  write_png(path, render_view(renderer, sim, view, robot, overlay));
}

VideoRecorder::VideoRecorder() = default;
VideoRecorder::~VideoRecorder() = default;

void VideoRecorder::start(const sim::Simulation& sim, const std::vector<std::string>& destinations,
                          const std::string& view, std::uint64_t every_steps, int robot,
                          bool overlay) {
  if (every_steps == 0) throw Error("video: expected a frame interval of at least one step");
  if (destinations.empty()) throw Error("video: expected a movie file (.apng, .mp4) or a folder");
  const CameraView camera = resolve_view(sim, view, robot);  // fail now, not at the first frame
  std::string movie, frames_dir;
  for (const std::string& d : destinations) {
    std::string& slot = is_movie_path(d) ? movie : frames_dir;
    if (!slot.empty())
      throw Error("video: two " + std::string(is_movie_path(d) ? "movies" : "folders") + " named");
    slot = d;
  }
  std::unique_ptr<MovieFile> opened;
  if (!movie.empty())
    opened = std::make_unique<MovieFile>(
        movie, camera.width, camera.height,
        1.0 / (static_cast<double>(every_steps) * sim.scene().physics.step));
  if (!frames_dir.empty()) make_frames_dir(frames_dir);
  movie_ = std::move(opened);
  frames_dir_ = frames_dir;
  view_ = view;
  every_ = every_steps;
  robot_ = robot;
  overlay_ = overlay;
  frames_ = 0;
  active_ = true;
}

void VideoRecorder::stop() {
  active_ = false;
  if (!movie_) return;
  std::unique_ptr<MovieFile> movie = std::move(movie_);
  movie->close();
}

void VideoRecorder::after_step(WorldRenderer& renderer, const sim::Simulation& sim) {
  if (!active_ || sim.steps() % every_ != 0) return;
  try {
    const RgbaImage image = render_view(renderer, sim, view_, robot_, overlay_);
    if (movie_) movie_->add(image);
    if (!frames_dir_.empty()) {
      char name[32];
      std::snprintf(name, sizeof name, "frame_%06llu.png",
                    static_cast<unsigned long long>(frames_));
      write_png((std::filesystem::path(frames_dir_) / name).string(), image, PngEncoding::Fast);
    }
  } catch (...) {
    active_ = false;  // one error, not one per step
    movie_.reset();   // an unfinished movie is removed
    throw;
  }
  ++frames_;
}

}  // namespace stride::render
