#pragma once
// Named viewpoints: built-in ones that frame a robot (or the origin without robots), and the
// scene's own <camera> elements.
#include <string>
#include <vector>

#include "simulator/render/camera.hpp"

namespace stride::sim {
class Simulation;
}

namespace stride::render {

// "follow" (the default), "front", "side", "top", then the scene's cameras.
std::vector<std::string> view_names(const sim::Simulation& sim);
// Built-in views frame robot `robot`. Throws stride::Error naming the known views when `name` is
// none of them.
CameraView resolve_view(const sim::Simulation& sim, const std::string& name, int robot = 0);

}  // namespace stride::render
