#pragma once
// What the LoLA process tests share: the two programs, a robot config written for a test, and
// fields read out of a run report.
#include <fstream>
#include <string>

#include "tests/lola/child_process.hpp"

namespace stride::test {

inline const std::string kStride = STRIDE_BINARY_DIR "/stride";
inline const std::string kStrideRobot = STRIDE_BINARY_DIR "/stride-robot";
inline const std::string kHipScene = STRIDE_SOURCE_DIR "/scenes/experiments/hip_medium.xml";
inline const std::string kHipConfig = STRIDE_SOURCE_DIR "/scenes/robots/nao/config/hip_walk.xml";

// A robot config in the scratch folder: `controller` is the inside of its <controller>.
inline std::string robot_config(const std::string& name, const std::string& controller,
                                const std::string& safety) {
  const std::string path = ChildProcess::scratch(name + ".xml");
  std::ofstream(path) << "<robot_config name=\"" << name << "\">\n"
                      << "  <model urdf=\"" STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf\"/>\n"
                      << "  <safety " << safety << "/>\n"
                      << "  <controller>" << controller << "</controller>\n"
                      << "</robot_config>\n";
  return path;
}

inline const std::string kStandController =
    "<provider representation=\"JointRequest\" module=\"Stand\"/>";

// The text of `"key": value` in a JSON report (the first one), without quotes.
inline std::string json_value(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  if (at == std::string::npos) return "";
  auto begin = json.find_first_not_of(" ", at + key.size() + 3);
  auto end = json.find_first_of(",}\n", begin);
  std::string v = json.substr(begin, end - begin);
  if (!v.empty() && v.front() == '"') v = v.substr(1, v.size() - 2);
  return v;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace stride::test
