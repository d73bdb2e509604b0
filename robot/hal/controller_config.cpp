#include "robot/hal/controller_config.hpp"

#include <algorithm>
#include <map>

#include "robot/core/physical_limits.hpp"

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

// The same provider or parameter twice in one <controller> or one <at> is an error naming both
// lines, not a silent "the last one wins".
using SeenSettings = std::map<std::string, std::string>;
void setting_once(const XmlElement& e, const ControllerChange& s, SeenSettings& seen) {
  const bool provider = s.kind == ControllerChange::Kind::Provider;
  const std::string key = (provider ? "provider " : "parameter ") + s.first;
  const auto [it, fresh] = seen.emplace(key, e.file() + ":" + std::to_string(e.line()));
  if (!fresh)
    e.fail(std::string(provider ? "the provider of " : "parameter ") + s.first +
           " given twice (first at " + it->second + ")");
}

// <at time="5s"> with <provider> and <parameter> children: applied at the first control frame
// at or after that time, in the order written.
void timed_changes(const XmlElement& e, ControllerConfig& cfg) {
  e.allow_only({"time"});
  const double time = e.number("time", Dimension::Time);
  if (!(time >= 0)) e.fail_attr("time", "expected a time >= 0");
  e.check_within("time", time, 0, limits::kMaxDuration, Dimension::Time);
  if (!e.raw()->FirstChildElement()) e.fail("expected <provider> or <parameter> inside <at>");
  SeenSettings seen;
  for (const XMLElement* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement()) {
    const XmlElement child(c, e.file());
    ControllerChange change =
        setting(child, "unknown element in <at> (expected provider or parameter)");
    setting_once(child, change, seen);
    change.time = time;
    cfg.changes.push_back(std::move(change));
  }
}

}  // namespace

ControllerConfig parse_controller(const XmlElement& e) {
  e.allow_only({});
  ControllerConfig cfg;
  SeenSettings seen;
  for (const XMLElement* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement()) {
    XmlElement child(c, e.file());
    if (child.name() == "at") {
      timed_changes(child, cfg);
      continue;
    }
    const ControllerChange s =
        setting(child, "unknown element in <controller> (expected provider, parameter or at)");
    setting_once(child, s, seen);
    (s.kind == ControllerChange::Kind::Provider ? cfg.providers : cfg.parameters)[s.first] =
        s.second;
  }
  std::stable_sort(cfg.changes.begin(), cfg.changes.end(),
                   [](const auto& a, const auto& b) { return a.time < b.time; });
  return cfg;
}

}  // namespace stride
