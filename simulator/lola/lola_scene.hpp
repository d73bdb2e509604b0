#pragma once
// A scene's robot made ready for a LoLA link, the one rule for `stride run --lola[-packets]` and
// for sweeps through LoLA: LoLA's 12 ms period unless the scene states one, and, when a LoLA
// client (a robot process) is its controller, no controller in this process.
#include <cstddef>

#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

enum class LolaController {
  InProcess,  // through LoLA's packets in this process (the scene's own controller)
  Client      // the LoLA client controls it
};

void prepare_lola_robot(SceneDescription& scene, std::size_t robot, LolaController controller);

}  // namespace stride::sim
