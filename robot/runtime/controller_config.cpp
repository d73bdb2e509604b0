#include "robot/runtime/controller_config.hpp"

#include <algorithm>

namespace stride {
namespace {

using tinyxml2::XMLElement;

// A <provider> or <parameter> element as (representation, module) or ("Module.field", value);
// anything else fails with `expected`.
ControllerChange setting(const XmlElement& e, const char* expected) {
  ControllerChange c;
  c.file = e.file();
  c.line = e.line();
  if (e.name() == "provider") {
    e.allow_only({"representation", "module"});
    c.kind = ControllerChange::Kind::Provider;
    c.first = e.text("representation");
    c.second = e.text("module");
  } else if (e.name() == "parameter") {
    e.allow_only({"module", "field", "value"});
    c.first = e.text("module") + "." + e.text("field");
    c.second = e.text("value");
  } else {
    e.fail(expected);
  }
  return c;
}

// <at time="5s"> with <provider> and <parameter> children: applied at the first control frame
// at or after that time, in the order written.
void timed_changes(const XmlElement& e, ControllerConfig& cfg) {
  e.allow_only({"time"});
  const double time = e.number("time", Dimension::Time);
  if (!(time >= 0)) e.fail_attr("time", "expected a time >= 0");
  if (!e.raw()->FirstChildElement()) e.fail("expected <provider> or <parameter> inside <at>");
  for (const XMLElement* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement()) {
    ControllerChange change = setting(XmlElement(c, e.file()),
                                      "unknown element in <at> (expected provider or parameter)");
    change.time = time;
    cfg.changes.push_back(std::move(change));
  }
}

}  // namespace

ControllerConfig parse_controller(const XmlElement& e) {
  e.allow_only({});
  ControllerConfig cfg;
  for (const XMLElement* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement()) {
    XmlElement child(c, e.file());
    if (child.name() == "at") {
      timed_changes(child, cfg);
      continue;
    }
    const ControllerChange s =
        setting(child, "unknown element in <controller> (expected provider, parameter or at)");
    (s.kind == ControllerChange::Kind::Provider ? cfg.providers : cfg.parameters)[s.first] =
        s.second;
  }
  std::stable_sort(cfg.changes.begin(), cfg.changes.end(),
                   [](const auto& a, const auto& b) { return a.time < b.time; });
  return cfg;
}

}  // namespace stride
