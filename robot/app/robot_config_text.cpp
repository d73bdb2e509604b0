#include "robot/app/robot_config_text.hpp"

#include <tinyxml2.h>

#include <charconv>

namespace stride {
namespace {

// Seconds in the shortest text that reads back to the same double, with the unit the parser
// wants.
std::string seconds(double s) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf - 1, s);
  return std::string(buf, r.ptr) + "s";
}

void add_setting(tinyxml2::XMLElement* parent, bool provider, const std::string& first,
                 const std::string& second) {
  tinyxml2::XMLElement* e = parent->InsertNewChildElement(provider ? "provider" : "parameter");
  if (provider) {
    e->SetAttribute("representation", first.c_str());
    e->SetAttribute("module", second.c_str());
    return;
  }
  const std::size_t dot = first.find('.');  // "Module.field.sub": the module is the first word
  e->SetAttribute("module", first.substr(0, dot).c_str());
  e->SetAttribute("field", first.substr(dot + 1).c_str());
  e->SetAttribute("value", second.c_str());
}

void add_controller(tinyxml2::XMLElement* root, const ControllerConfig& c) {
  tinyxml2::XMLElement* e = root->InsertNewChildElement("controller");
  for (const auto& [representation, module] : c.providers)
    add_setting(e, true, representation, module);
  for (const auto& [key, value] : c.parameters) add_setting(e, false, key, value);
  // Changes in time order; consecutive ones at one time share an <at>, keeping their order.
  tinyxml2::XMLElement* at = nullptr;
  double at_time = -1;
  for (const ControllerChange& change : c.changes) {
    if (!at || change.time != at_time) {
      at = e->InsertNewChildElement("at");
      at->SetAttribute("time", seconds(change.time).c_str());
      at_time = change.time;
    }
    add_setting(at, change.kind == ControllerChange::Kind::Provider, change.first, change.second);
  }
}

}  // namespace

std::string robot_config_xml(const RobotConfig& config) {
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  tinyxml2::XMLElement* root = doc.NewElement("robot_config");
  doc.InsertEndChild(root);
  root->SetAttribute("name", config.name.c_str());
  root->InsertNewChildElement("model")->SetAttribute("urdf", config.urdf.c_str());
  tinyxml2::XMLElement* lola = root->InsertNewChildElement("lola");
  lola->SetAttribute("socket", config.lola_socket.c_str());
  lola->SetAttribute("period", seconds(config.period).c_str());
  lola->SetAttribute("connect_timeout", seconds(config.connect_timeout).c_str());
  tinyxml2::XMLElement* safety = root->InsertNewChildElement("safety");
  safety->SetAttribute("link_timeout", seconds(config.link_timeout).c_str());
  safety->SetAttribute("on_module_error", config.stop_on_module_error ? "stop" : "continue");
  add_controller(root, config.controller);
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace stride
