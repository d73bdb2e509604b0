#include "robot/model/urdf_validation.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

#include <tinyxml2.h>

#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/physical_limits.hpp"
#include "robot/core/xml_error.hpp"
#include "robot/model/inertia_check.hpp"
#include "robot/model/urdf_tree_check.hpp"

namespace stride::model {
namespace {

using tinyxml2::XMLElement;

struct Checker {
  const std::string& source;

  [[noreturn]] void fail(const XMLElement* e, const std::string& msg) const {
    throw error_at(source, e ? e->GetLineNum() : 0, msg);
  }

  // The attribute's numbers; each must parse and be finite.
  std::vector<double> numbers(const XMLElement* e, const char* attr,
                              const std::string& what) const {
    std::vector<double> out;
    const char* text = e->Attribute(attr);
    if (!text) return out;
    // Split at whitespace by hand, without a stream per attribute (a NAO URDF has hundreds).
    const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    for (const char* p = text;;) {
      while (*p && space(*p)) ++p;
      if (!*p) break;
      const char* token_end = p;
      while (*token_end && !space(*token_end)) ++token_end;
      const std::string token(p, token_end);
      char* end = nullptr;
      const double v = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0' || !std::isfinite(v))
        fail(e, what + ": attribute '" + attr + "' = '" + text + "' (expected finite numbers)");
      out.push_back(v);
      p = token_end;
    }
    return out;
  }

  // Exactly `count` numbers (when the attribute is present), each with |v| <= `bound`.
  std::vector<double> bounded(const XMLElement* e, const char* attr, const std::string& what,
                              std::size_t count, double bound, const char* unit) const {
    const auto v = numbers(e, attr, what);
    if (!e->Attribute(attr)) return v;
    if (v.size() != count)
      fail(e, what + ": attribute '" + attr + "' = '" + e->Attribute(attr) + "' (expected " +
                  std::to_string(count) + (count == 1 ? " number)" : " numbers)"));
    for (double x : v)
      if (std::abs(x) > bound)
        fail(e, what + ": " + attr + " " + short_number(x) + (*unit ? " " : "") + unit +
                    " outside [-" + short_number(bound) + ", " + short_number(bound) + "]");
    return v;
  }

  double required_number(const XMLElement* e, const char* attr, const std::string& what) const {
    if (!e->Attribute(attr)) fail(e, what + ": missing attribute '" + std::string(attr) + "'");
    const auto v = numbers(e, attr, what);
    if (v.size() != 1)
      fail(e, what + ": attribute '" + attr + "' = '" + e->Attribute(attr) +
                  "' (expected one number)");
    return v[0];
  }

  // A required number in [lo, hi], named with its unit when it is not.
  double in_range(const XMLElement* e, const char* attr, const std::string& what, double lo,
                  double hi, const char* unit) const {
    const double v = required_number(e, attr, what);
    if (!(v >= lo && v <= hi))
      fail(e, what + ": " + attr + " " + short_number(v) + " " + unit + " outside [" +
                  short_number(lo) + ", " + short_number(hi) + "]");
    return v;
  }

  void check_all_numbers(const XMLElement* e, const std::string& what) const {
    static constexpr const char* kNumeric[] = {
        "xyz",    "rpy",      "value",      "size",   "radius",  "length",  "ixx",
        "ixy",    "ixz",      "iyy",        "iyz",    "izz",     "lower",   "upper",
        "effort", "velocity", "multiplier", "offset", "damping", "friction"};
    for (const char* a : kNumeric) numbers(e, a, what);
    for (const XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
      check_all_numbers(c, what);
  }

  void check_origin(const XMLElement* parent, const std::string& what) const {
    if (const XMLElement* o = parent->FirstChildElement("origin")) {
      bounded(o, "xyz", what + " origin", 3, limits::kMaxLength, "m");
      bounded(o, "rpy", what + " origin", 3, 1e3, "rad");
    }
  }

  // Returns the link's mass [kg].
  double check_inertial(const XMLElement* inertial, const std::string& what) const {
    const XMLElement* mass = inertial->FirstChildElement("mass");
    if (!mass) fail(inertial, what + ": <inertial> without <mass>");
    const double kg = in_range(mass, "value", what + " mass", 0, limits::kMaxMass, "kg");
    check_origin(inertial, what + " inertial");
    // A mass with no rotational inertia is a body the solver cannot turn: ODE's step goes NaN
    // and aborts. Only a massless frame link may leave its inertia out (or zero).
    const auto frame_only = [&](const XMLElement* e, const char* missing) {
      if (kg > limits::kMaxFrameMass)
        fail(e, what + ": " + missing + " for a mass of " + short_number(kg) +
                    " kg (expected principal moments in [" + short_number(limits::kMinInertia) +
                    ", " + short_number(limits::kMaxInertia) + "] kg*m^2; only a link of at most " +
                    short_number(limits::kMaxFrameMass) + " kg may have none)");
    };
    const XMLElement* in = inertial->FirstChildElement("inertia");
    if (!in) {
      frame_only(inertial, "<inertial> without <inertia>");
      return kg;
    }
    double v[6];
    const char* names[] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
    for (int k = 0; k < 6; ++k) v[k] = required_number(in, names[k], what + " inertia");
    Eigen::Matrix3d i;
    i << v[0], v[1], v[2], v[1], v[3], v[4], v[2], v[4], v[5];
    if (i.isZero(0)) {
      frame_only(in, "zero inertia");
      return kg;
    }
    if (const std::string problem = inertia_problem(i); !problem.empty())
      fail(in, what + ": inertia " + problem);
    return kg;
  }

  void check_shape(const XMLElement* shape, const std::string& what) const {
    const std::string_view kind = shape->Name();
    const auto length = [&](const char* attr) {
      in_range(shape, attr, what + " " + std::string(kind), limits::kMinLength, limits::kMaxLength,
               "m");
    };
    if (kind == "mesh")
      fail(shape,
           what + ": mesh collision geometry is not supported (expected box, cylinder or sphere)");
    if (kind == "box") {
      if (!shape->Attribute("size")) fail(shape, what + " box: missing attribute 'size'");
      const auto size = numbers(shape, "size", what + " box");
      if (size.size() != 3)
        fail(shape,
             what + " box: size '" + shape->Attribute("size") + "' (expected three lengths)");
      for (double s : size)
        if (!(s >= limits::kMinLength && s <= limits::kMaxLength))
          fail(shape, what + " box: size " + short_number(s) + " m outside [" +
                          short_number(limits::kMinLength) + ", " +
                          short_number(limits::kMaxLength) + "]");
    } else if (kind == "sphere") {
      length("radius");
    } else if (kind == "cylinder") {
      length("radius");
      length("length");
    } else {
      fail(shape, what + ": unknown geometry <" + std::string(kind) +
                      "> (expected box, cylinder or sphere)");
    }
  }

  UrdfLinkRecord check_link(const XMLElement* link) const {
    const char* name = link->Attribute("name");
    if (!name) fail(link, "<link> without a name");
    const std::string what = std::string("link '") + name + "'";
    check_all_numbers(link, what);
    double kg = 0;
    if (const XMLElement* inertial = link->FirstChildElement("inertial"))
      kg = check_inertial(inertial, what);
    for (const XMLElement* col = link->FirstChildElement("collision"); col;
         col = col->NextSiblingElement("collision")) {
      const XMLElement* geom = col->FirstChildElement("geometry");
      if (!geom || !geom->FirstChildElement())
        fail(col, what + ": <collision> without a <geometry> shape");
      check_origin(col, what + " collision");
      check_shape(geom->FirstChildElement(), what);
      // Contact on a near-massless body (a frame link gets 1e-6 kg) drives ODE's step to NaN.
      if (kg <= limits::kMaxFrameMass)
        fail(col,
             what + ": a collision shape on a link of mass " + short_number(kg) +
                 " kg (a frame link touches nothing; expected an <inertial> with a mass over " +
                 short_number(limits::kMaxFrameMass) + " kg and its inertia)");
    }
    return {name, link->GetLineNum()};
  }

  std::string link_of(const XMLElement* joint, const char* end, const std::string& what) const {
    const XMLElement* e = joint->FirstChildElement(end);
    const char* link = e ? e->Attribute("link") : nullptr;
    if (!link) fail(joint, what + ": needs <parent link=...> and <child link=...>");
    return link;
  }

  void check_limit(const XMLElement* joint, std::string_view t, const std::string& what) const {
    const XMLElement* limit = joint->FirstChildElement("limit");
    if (!limit) {
      if (t == "revolute" || t == "prismatic")
        fail(joint, what + ": " + std::string(t) +
                        " joint without <limit> (expected lower, upper, effort, velocity)");
      return;
    }
    const std::string w = what + " limit";
    const bool needs_range = t == "revolute" || t == "prismatic";
    const auto bound = [&](const char* attr) {
      if (needs_range || limit->Attribute(attr))
        return in_range(limit, attr, w, -limits::kMaxJointRange, limits::kMaxJointRange,
                        t == "prismatic" ? "m" : "rad");
      return 0.0;
    };
    const double lo = bound("lower");
    const double hi = bound("upper");
    if (lo > hi) fail(limit, what + ": lower limit above upper limit");
    in_range(limit, "effort", w, 0, limits::kMaxForce, t == "prismatic" ? "N" : "N*m");
    in_range(limit, "velocity", w, 0, limits::kMaxSpeed, t == "prismatic" ? "m/s" : "rad/s");
  }

  UrdfJointRecord check_joint(const XMLElement* joint) const {
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
    UrdfJointRecord r{name,
                      type,
                      link_of(joint, "parent", what),
                      link_of(joint, "child", what),
                      "",
                      joint->GetLineNum()};
    check_origin(joint, what);
    if (const XMLElement* axis = joint->FirstChildElement("axis")) {
      if (!axis->Attribute("xyz"))  // the URDF parser would read it as the zero vector
        fail(axis,
             what + ": <axis> without attribute 'xyz' (expected a direction, e.g. \"0 0 1\")");
      const auto a = bounded(axis, "xyz", what + " axis", 3, 1e6, "");
      if (a.size() == 3 && std::hypot(a[0], a[1], a[2]) < 1e-9)
        fail(axis,
             what + ": zero axis '" + axis->Attribute("xyz") + "' (expected a non-zero direction)");
    }
    check_limit(joint, t, what);
    if (const XMLElement* mimic = joint->FirstChildElement("mimic")) {
      if (!mimic->Attribute("joint")) fail(mimic, what + ": <mimic> without attribute 'joint'");
      r.mimic = mimic->Attribute("joint");
      bounded(mimic, "multiplier", what + " mimic", 1, limits::kMaxMimicFactor, "");
      bounded(mimic, "offset", what + " mimic", 1, limits::kMaxMimicFactor, "");
    }
    return r;
  }
};

}  // namespace

void validate_urdf_text(const std::string& xml, const std::string& source_name) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(source_name, doc.ErrorLineNum(), xml_error_text(doc));
  const XMLElement* robot = doc.RootElement();
  Checker c{source_name};
  if (!robot || std::string_view(robot->Name()) != "robot")
    c.fail(robot, "expected <robot> as the root element");
  int count = 0;  // a robot over the size limit is refused before any other check
  const XMLElement* too_many = nullptr;
  for (const XMLElement* e = robot->FirstChildElement("link"); e; e = e->NextSiblingElement("link"))
    if (++count == limits::kMaxLinks + 1) too_many = e;
  if (too_many)
    c.fail(too_many, "robot with " + std::to_string(count) + " links (at most " +
                         std::to_string(limits::kMaxLinks) + ")");
  std::vector<UrdfLinkRecord> links;
  std::vector<UrdfJointRecord> joints;
  for (const XMLElement* e = robot->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string_view n = e->Name();
    if (n == "link")
      links.push_back(c.check_link(e));
    else if (n == "joint")
      joints.push_back(c.check_joint(e));
  }
  check_urdf_tree(links, joints, source_name);
}

}  // namespace stride::model
