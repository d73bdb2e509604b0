// Every scene shipped under scenes/ (robot descriptions and sweep files aside) loads, builds its
// world and its controllers, and runs, so a broken experiment scene shows here rather than in a
// sweep.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/session/sim_session.hpp"
#include "robot/core/error.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> scenes;
  const fs::path root = fs::path(STRIDE_SOURCE_DIR) / "scenes";
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const fs::path rel = fs::relative(e.path(), root);
    const bool sweep = e.path().filename().string().ends_with(".sweep.xml");  // shipped_sweeps
    if (e.path().extension() == ".xml" && !sweep && *rel.begin() != "robots")
      scenes.push_back(e.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(ShippedScenes, EveryOneLoadsAndSteps) {
  const auto scenes = shipped_scenes();
  EXPECT_GE(scenes.size(), 50u);  // walking, push, landing, swing-leg and the experiment sets
  for (const fs::path& p : scenes) {
    SCOPED_TRACE(p.string());
    try {
      console::SimSession session(p.string());
      session.simulation().run_for(0.05);  // a few control frames: the controllers run too
      EXPECT_GE(session.simulation().time(), 0.05 - 1e-9);
    } catch (const Error& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

}  // namespace
}  // namespace stride
