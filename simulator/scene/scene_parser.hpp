#pragma once
// Scene XML -> SceneDescription. Every error: "file:line: <element>: what was expected".
#include <string>

#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

SceneDescription parse_scene_file(const std::string& path);
// For fuzzing and tests: `text` as if it were the file `virtual_path` (includes resolve from its
// directory).
SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path);

}  // namespace stride::sim
