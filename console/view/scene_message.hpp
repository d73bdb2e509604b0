#pragma once
// The `scene` message (PROTOCOL.md): static boxes and ramps, uneven tiles, and each robot's links
// with their collision shapes, from a scene description and the robots' models.
#include <string>
#include <vector>

#include "console/view/view_json.hpp"
#include "robot/model/robot_model.hpp"
#include "simulator/scene/scene_description.hpp"

namespace stride::view {

struct SceneRobot {
  std::string name;
  const model::RobotModel* model = nullptr;
};

// A robot's links as the scene lists them: name, side (left/right/centre) and shapes.
Json robot_links_json(const model::RobotModel& model);

// `scene` may be null (a robot without a scene: a remote robot or a log): no statics then.
Json scene_message(const std::string& name, const sim::SceneDescription* scene,
                   const std::vector<SceneRobot>& robots);

}  // namespace stride::view
