#pragma once
// Draws a physics world's collision geometry (what the solver sees) from a camera into an image.
#include <memory>
#include <vector>

#include "simulator/render/camera.hpp"
#include "simulator/render/image.hpp"
#include "simulator/scene/scene_description.hpp"

namespace stride::sim {
class PhysicsWorld;
}

namespace stride::render {

class OffscreenGl;

class WorldRenderer {
 public:
  WorldRenderer();
  ~WorldRenderer();
  WorldRenderer(const WorldRenderer&) = delete;
  WorldRenderer& operator=(const WorldRenderer&) = delete;

  // `lights` empty: one default light from above and behind the camera's left.
  RgbaImage render(const sim::PhysicsWorld& world, const CameraView& view,
                   const std::vector<sim::SceneLight>& lights);

 private:
  std::unique_ptr<OffscreenGl> gl_;  // kept while the image size stays: contexts are slow to make
};

}  // namespace stride::render
