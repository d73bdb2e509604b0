#pragma once
// Records `seconds` of a scene's robot 0 to a log in the temporary directory, as `stride run
// --log` does; returns its path.
#include <filesystem>
#include <string>

#include "console/session/sim_session.hpp"
#include "robot/runtime/runtime.hpp"

namespace stride::test {

inline std::string record_log(sim::SceneDescription scene, double seconds,
                              const std::string& name) {
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  console::SimSession session(std::move(scene));
  session.runtime(0)->start_log(path);
  session.simulation().run_for(seconds);
  session.runtime(0)->stop_log();
  return path;
}

}  // namespace stride::test
