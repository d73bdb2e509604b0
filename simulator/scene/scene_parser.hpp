#pragma once
// Scene XML -> SceneDescription. Every error: "file:line: <element>: what was expected".
#include <string>
#include <utility>
#include <vector>

#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

// A relative path not found from the working directory is looked up in the data directory.
SceneDescription parse_scene_file(const std::string& path);

// <physics> attributes set over a scene's own, e.g. {{"iterations", "40"}, {"sor", "1.0"}}: one
// solver setting tried on an otherwise unchanged scene. A spring (contact_stiffness/damping)
// replaces the scene's contact_erp/cfm and the other way round.
using PhysicsAttributes = std::vector<std::pair<std::string, std::string>>;
SceneDescription parse_scene_file(const std::string& path, const PhysicsAttributes& physics_over);
// "iterations=40,sor=1.0" -> its attributes, each value checked as a scene's <physics> would be;
// throws stride::Error naming the setting and the attribute.
PhysicsAttributes parse_physics_setting(const std::string& text);
// For fuzzing and tests: `text` as if it were the file `virtual_path` (includes resolve from its
// directory).
SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path);

}  // namespace stride::sim
