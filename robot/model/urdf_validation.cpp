#include "robot/model/urdf_validation.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string_view>

#include <tinyxml2.h>

#include "robot/core/error.hpp"
#include "robot/core/xml_error.hpp"

namespace stride::model {
namespace {

using tinyxml2::XMLElement;

struct Checker {
  const std::string& source;

  [[noreturn]] void fail(const XMLElement* e, const std::string& msg) const {
    throw error_at(source, e ? e->GetLineNum() : 0, msg);
  }

  // Every number in the attribute must parse and be finite.
  void check_numbers(const XMLElement* e, const char* attr, const std::string& what) const {
    const char* text = e->Attribute(attr);
    if (!text) return;
    std::istringstream in(text);
    std::string tok;
    while (in >> tok) {
      char* end = nullptr;
      double v = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != '\0' || !std::isfinite(v))
        fail(e, what + ": attribute '" + attr + "' = '" + text + "' (expected finite numbers)");
    }
  }

  double required_number(const XMLElement* e, const char* attr, const std::string& what) const {
    const char* text = e->Attribute(attr);
    if (!text) fail(e, what + ": missing attribute '" + std::string(attr) + "'");
    check_numbers(e, attr, what);
    return std::strtod(text, nullptr);
  }

  void check_all_numbers(const XMLElement* e, const std::string& what) const {
    static constexpr const char* kNumeric[] = {
        "xyz",    "rpy",      "value",      "size",   "radius",  "length",  "ixx",
        "ixy",    "ixz",      "iyy",        "iyz",    "izz",     "lower",   "upper",
        "effort", "velocity", "multiplier", "offset", "damping", "friction"};
    for (const char* a : kNumeric) check_numbers(e, a, what);
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      check_all_numbers(c, what);
  }

  void check_link(const XMLElement* link) const {
    const char* name = link->Attribute("name");
    if (!name) fail(link, "<link> without a name");
    const std::string what = std::string("link '") + name + "'";
    check_all_numbers(link, what);
    if (const XMLElement* inertial = link->FirstChildElement("inertial")) {
      const XMLElement* mass = inertial->FirstChildElement("mass");
      if (!mass) fail(inertial, what + ": <inertial> without <mass>");
      double m = required_number(mass, "value", what + " mass");
      if (m < 0)
        fail(mass, what + ": negative mass " + mass->Attribute("value") + " (expected >= 0 kg)");
      if (const XMLElement* in = inertial->FirstChildElement("inertia")) {
        for (const char* d : {"ixx", "iyy", "izz"})
          if (required_number(in, d, what + " inertia") < 0)
            fail(in, what + ": negative inertia " + d + " (expected >= 0 kg*m^2)");
      }
    }
    for (const XMLElement* col = link->FirstChildElement("collision"); col;
         col = col->NextSiblingElement("collision")) {
      const XMLElement* geom = col->FirstChildElement("geometry");
      if (!geom || !geom->FirstChildElement())
        fail(col, what + ": <collision> without a <geometry> shape");
      const XMLElement* shape = geom->FirstChildElement();
      const std::string_view kind = shape->Name();
      if (kind == "mesh")
        fail(
            shape,
            what + ": mesh collision geometry is not supported (expected box, cylinder or sphere)");
      if (kind == "box") {
        required_number(shape, "size", what + " box");
      } else if (kind == "sphere") {
        if (required_number(shape, "radius", what + " sphere") <= 0)
          fail(shape, what + ": sphere radius must be > 0");
      } else if (kind == "cylinder") {
        if (required_number(shape, "radius", what + " cylinder") <= 0 ||
            required_number(shape, "length", what + " cylinder") <= 0)
          fail(shape, what + ": cylinder radius and length must be > 0");
      } else {
        fail(shape, what + ": unknown geometry <" + std::string(kind) +
                        "> (expected box, cylinder or sphere)");
      }
    }
  }

  void check_joint(const XMLElement* joint) const {
    const char* name = joint->Attribute("name");
    const char* type = joint->Attribute("type");
    if (!name) fail(joint, "<joint> without a name");
    const std::string what = std::string("joint '") + name + "'";
    if (!type) fail(joint, what + ": missing attribute 'type'");
    check_all_numbers(joint, what);
    const std::string_view t = type;
    if (t != "revolute" && t != "continuous" && t != "prismatic" && t != "fixed")
      fail(joint, what + ": unsupported type '" + std::string(t) +
                      "' (expected revolute, continuous, prismatic or fixed)");
    if (!joint->FirstChildElement("parent") || !joint->FirstChildElement("child"))
      fail(joint, what + ": needs <parent link=...> and <child link=...>");
    if (t == "revolute" || t == "prismatic") {
      const XMLElement* limit = joint->FirstChildElement("limit");
      if (!limit)
        fail(joint, what + ": " + std::string(t) +
                        " joint without <limit> (expected lower, upper, effort, velocity)");
      double lo = required_number(limit, "lower", what + " limit");
      double hi = required_number(limit, "upper", what + " limit");
      if (lo > hi) fail(limit, what + ": lower limit above upper limit");
      if (required_number(limit, "effort", what + " limit") < 0 ||
          required_number(limit, "velocity", what + " limit") < 0)
        fail(limit, what + ": effort and velocity limits must be >= 0");
    }
  }
};

}  // namespace

void validate_urdf_text(const std::string& xml, const std::string& source_name) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(source_name, doc.ErrorLineNum(),
                   xml_error_text(doc));
  const XMLElement* robot = doc.RootElement();
  Checker c{source_name};
  if (!robot || std::string_view(robot->Name()) != "robot")
    c.fail(robot, "expected <robot> as the root element");
  for (const XMLElement* e = robot->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string_view n = e->Name();
    if (n == "link")
      c.check_link(e);
    else if (n == "joint")
      c.check_joint(e);
  }
}

}  // namespace stride::model
