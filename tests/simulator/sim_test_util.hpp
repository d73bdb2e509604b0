#pragma once
// Helpers for simulator tests: scenes written from strings, paths into the source tree.
#include <memory>
#include <string>

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
