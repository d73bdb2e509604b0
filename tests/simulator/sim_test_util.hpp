#pragma once
// Helpers for simulator tests: scenes written from strings, paths into the source tree.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "simulator/scene/scene_parser.hpp"
#include "simulator/simulation.hpp"

namespace stride::test {

inline std::string source_path(const std::string& rel) {
  return std::string(STRIDE_SOURCE_DIR) + "/" + rel;
}

// A scene given as text, resolved as if it were the file tests/data/<name>.
inline std::unique_ptr<sim::Simulation> scene_from_text(const std::string& xml,
                                                        const std::string& name = "inline.xml") {
  return std::make_unique<sim::Simulation>(
      sim::parse_scene_text(xml, source_path("tests/data/" + name)));
}

}  // namespace stride::test

namespace stride::test {

// The engines a physics test runs on: ODE, and MuJoCo when it is built in.
inline std::vector<std::string> engines() {
#ifdef STRIDE_HAVE_MUJOCO
  return {"ode", "mujoco"};
#else
  return {"ode"};
#endif
}

// Names a parametrised test's instance by its engine: Engines/NaoStanding.X/mujoco.
inline std::string engine_name(const ::testing::TestParamInfo<std::string>& info) {
  return info.param;
}

// The scene text on `engine`: ODE leaves it as written; another engine is named in <physics>.
inline std::string on_engine(const std::string& xml, const std::string& engine) {
  if (engine == "ode") return xml;
  const std::string attr = " engine=\"" + engine + "\"";
  if (const auto p = xml.find("<physics"); p != std::string::npos)
    return xml.substr(0, p + 8) + attr + xml.substr(p + 8);
  const auto s = xml.find("<scene>");
  return xml.substr(0, s + 7) + "<physics" + attr + "/>" + xml.substr(s + 7);
}

}  // namespace stride::test
