#pragma once
// A scene file with some of its XML attributes changed, then parsed as usual: how a sweep varies
// any scene attribute (floor height and tilt, friction, pushes, motor gains, solver, URDF).
#include <string>
#include <vector>

#include "console/sweep/sweep_spec.hpp"
#include "simulator/scene/scene_description.hpp"

namespace stride::sweep {

// `edits` are Settings whose target is "scene:<path>@<attribute>": path segments joined by '/',
// each an element name, optionally `[N]` (the N-th such child, from 1) or `[attr=value]` (the
// child whose attribute has that text). Throws stride::Error naming the target when no element
// matches or the edited scene does not parse (the scene parser's message follows).
sim::SceneDescription load_edited_scene(const std::string& path, const std::vector<Setting>& edits);

// Checks a "scene:..." target's syntax; throws stride::Error saying what was expected.
void check_scene_target(const std::string& target);

}  // namespace stride::sweep
