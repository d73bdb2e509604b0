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
    const std::string name = e.path().filename().string();
    // Sweep and tuning files: shipped_sweeps_test, tests/tune.
    const bool sweep = name.ends_with(".sweep.xml") || name.ends_with(".tune.xml");
    // scenes/hostile/ holds the broken cases of the overnight sweep (tested below).
    if (e.path().extension() == ".xml" && !sweep && *rel.begin() != "robots" &&
        *rel.begin() != "hostile")
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

// The overnight sweep's broken cases: the robot that cannot be simulated is refused at load with
// the URDF's file:line; the walk pushed apart loads and runs until its push.
TEST(ShippedScenes, TheHostileCasesFailAsIntended) {
  const fs::path dir = fs::path(STRIDE_SOURCE_DIR) / "scenes" / "hostile";
  try {
    console::SimSession session((dir / "broken_urdf.xml").string());
    ADD_FAILURE() << "broken_urdf.xml loaded";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("broken_inertia.urdf:7: link 'base': inertia violates the triangle "
                        "inequality"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find('\n'), std::string::npos);
  }
  console::SimSession pushed((dir / "pushed_apart_walk.xml").string());
  pushed.simulation().run_for(0.05);
  EXPECT_GE(pushed.simulation().time(), 0.05 - 1e-9);
}

}  // namespace
}  // namespace stride
