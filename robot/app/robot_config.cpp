#include "robot/app/robot_config.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "robot/core/error.hpp"
#include "robot/core/xml_error.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using tinyxml2::XMLElement;

void no_children(const XmlElement& e) {
  if (e.raw()->FirstChildElement())
    XmlElement(e.raw()->FirstChildElement(), e.file())
        .fail("unexpected child element of <" + std::string(e.name()) + ">");
}

void read_model(const XmlElement& e, RobotConfig& c) {
  e.allow_only({"urdf"});
  no_children(e);
  fs::path p(e.text("urdf"));
  if (p.is_relative()) p = fs::path(c.file).parent_path() / p;
  c.urdf = p.lexically_normal().string();
}

void read_lola(const XmlElement& e, RobotConfig& c) {
  e.allow_only({"socket", "period", "connect_timeout"});
  no_children(e);
  c.lola_socket = e.text_or("socket", c.lola_socket);
  if (c.lola_socket.empty() || c.lola_socket.size() > 100)
    e.fail_attr("socket", "expected a path of 1 to 100 characters");
  c.period = e.number_or("period", c.period, Dimension::Time);
  if (!(c.period >= 0.001 && c.period <= 1)) e.fail_attr("period", "expected 1 ms to 1 s");
  c.connect_timeout = e.number_or("connect_timeout", c.connect_timeout, Dimension::Time);
  if (!(c.connect_timeout >= 0 && c.connect_timeout <= 3600))
    e.fail_attr("connect_timeout", "expected a time from 0 to 1 hour");
}

void read_safety(const XmlElement& e, RobotConfig& c) {
  e.allow_only({"link_timeout", "on_module_error"});
  no_children(e);
  c.link_timeout = e.number_or("link_timeout", c.link_timeout, Dimension::Time);
  if (!(c.link_timeout >= 0 && c.link_timeout <= 3600))
    e.fail_attr("link_timeout", "expected a time from 0 to 1 hour");
  c.stop_on_module_error = e.choice_or("on_module_error", {"continue", "stop"}, 0) == 1;
}

RobotConfig parse(const std::string& text, const std::string& path) {
  RobotConfig c;
  c.file = path;
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(path, doc.ErrorLineNum(), xml_error_text(doc));
  const XMLElement* root = doc.RootElement();
  if (!root || std::string_view(root->Name()) != "robot_config")
    throw error_at(path, root ? root->GetLineNum() : 1,
                   "expected <robot_config> as the root element");
  const XmlElement top(root, path);
  top.allow_only({"name"});
  c.name = top.text_or("name", c.name);
  bool model = false, controller = false;
  for (const XMLElement* x = root->FirstChildElement(); x; x = x->NextSiblingElement()) {
    const XmlElement e(x, path);
    const std::string_view n = e.name();
    const bool repeated = (n == "model" && model) || (n == "controller" && controller);
    if (repeated) e.fail("one <" + std::string(n) + "> per robot config");
    if (n == "model") {
      read_model(e, c);
      model = true;
    } else if (n == "lola") {
      read_lola(e, c);
    } else if (n == "safety") {
      read_safety(e, c);
    } else if (n == "controller") {
      c.controller = parse_controller(e);
      controller = true;
    } else {
      e.fail("unknown element (expected model, lola, safety or controller)");
    }
  }
  if (!model) top.fail("expected a <model urdf=\"...\"> (the robot the controller computes with)");
  if (!controller) top.fail("expected a <controller> (as a scene's robot has)");
  return c;
}

}  // namespace

RobotConfig parse_robot_config_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ":0: cannot open robot config file");
  std::stringstream ss;
  ss << in.rdbuf();
  return parse(ss.str(), path);
}

RobotConfig parse_robot_config_text(const std::string& text, const std::string& virtual_path) {
  return parse(text, virtual_path);
}

}  // namespace stride
