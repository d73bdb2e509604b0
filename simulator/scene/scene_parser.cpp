#include "simulator/scene/scene_parser.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "robot/core/physical_limits.hpp"
#include "robot/core/pose.hpp"
#include "robot/core/xml_element.hpp"
#include "robot/core/xml_error.hpp"
#include "robot/hal/controller_config.hpp"
#include "simulator/scene/contact_law_parser.hpp"
#include "simulator/scene/contact_softness.hpp"
#include "simulator/scene/device_parser.hpp"
#include "simulator/scene/include_walk.hpp"
#include "simulator/scene/mujoco_options.hpp"
#include "simulator/scene/robot_override_file.hpp"
#include "simulator/scene/scene_limits.hpp"
#include "simulator/scene/solver_names.hpp"

namespace stride::sim {
namespace {

namespace fs = std::filesystem;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

constexpr double kMaxGyroBias = 10;    // rad/s: beyond any gyro's range
constexpr int kMaxRobotIncludes = 64;  // robot override files per scene
constexpr double kMaxAngle = 1e3;      // rad: |roll|, |pitch|, |yaw| of anything placed

class Parser {
 public:
  explicit Parser(SceneDescription& out, PhysicsAttributes physics_over = {})
      : out_(out), physics_over_(std::move(physics_over)) {}

  // A scene without <physics> still takes the attributes set over it, on the defaults.
  void physics_over_defaults() {
    if (physics_seen_ || physics_over_.empty()) return;
    XMLDocument doc;
    doc.Parse("<physics/>");
    physics(XmlElement(doc.RootElement(), out_.file));
  }

  // What needs the whole scene: the contact law against <physics>, the engine and the surfaces.
  void finish() { finish_contact_law(out_, replaced_, unstated_); }

  void parse_file(const std::string& path) { walk_.walk_file(path); }
  void parse_text(const std::string& text, const std::string& path) { walk_.walk_text(text, path); }

 private:
  // Every file's <scene> root names the scene (the first name wins).
  void scene_root(const XmlElement& scene) {
    scene.allow_only({"name"});
    if (out_.name.empty())
      out_.name = scene.text_or("name", fs::path(scene.file()).stem().string());
  }

  void element(const XmlElement& e) {
    const std::string_view n = e.name();
    const bool unstated = !e.has("friction");  // such a surface takes the law's
    if (n == "physics") {
      physics(e);
    } else if (n == "contact") {
      no_children(e);
      contact(e);
    } else if (n == "ground") {
      ground(e);
      unstated_.ground = unstated;
    } else if (n == "box" || n == "ramp") {
      n == "box" ? box(e) : ramp(e);
      if (unstated) unstated_.boxes.push_back(out_.boxes.size() - 1);
    } else if (n == "uneven") {
      uneven(e);
      if (unstated) unstated_.uneven.push_back(out_.uneven.size() - 1);
    } else if (n == "robot")
      robot(e);
    else if (n == "push")
      push(e);
    else if (n == "camera")
      camera(e);
    else if (n == "light")
      light(e);
    else
      e.fail(
          "unknown element (expected physics, contact, ground, box, ramp, uneven, robot, push, "
          "camera, light or include)");
  }

  // <physics>, <ground>: one per scene, includes counted; a second one names both places.
  void once(const XmlElement& e) {
    const std::string here = e.file() + ":" + std::to_string(e.line());
    const auto [it, fresh] = seen_once_.emplace(std::string(e.name()), here);
    if (!fresh) e.fail("given twice (first at " + it->second + "; expected one per scene)");
  }

  // <contact>: one per scene, but the scene's own replaces one from a file it includes (a study
  // that includes a shipped scene states its own law over the shipped one).
  void contact(const XmlElement& e) {
    const auto it = seen_once_.find("contact");
    if (it != seen_once_.end() && law_included_ && e.file() == out_.file) seen_once_.erase(it);
    once(e);
    law_included_ = e.file() != out_.file;
    parse_contact_law(e, out_.physics);
  }

  // Boxes, ramps and uneven tiles together stay within the scene limit.
  void add_static_shapes(const XmlElement& e, long n) {
    static_shapes_ += n;
    if (static_shapes_ > scene_limits::kMaxStaticGeoms)
      e.fail("the scene's static shapes would number " + std::to_string(static_shapes_) +
             " (boxes, ramps and uneven tiles; at most " +
             std::to_string(scene_limits::kMaxStaticGeoms) + ")");
  }

  void no_children(const XmlElement& e) {
    if (e.raw()->FirstChildElement())
      XmlElement(e.raw()->FirstChildElement(), e.file())
          .fail("unexpected child element of <" + std::string(e.name()) + ">");
  }

  void physics(const XmlElement& e) {
    physics_seen_ = true;
    set_physics_over(e);
    for (const char* a : kReplacedByLaw)
      if (e.has(a) && replaced_.attr.empty()) replaced_ = {e.file(), a, e.line()};
    e.allow_only({"engine",
                  "step",
                  "solver",
                  "iterations",
                  "sor",
                  "erp",
                  "cfm",
                  "contact_erp",
                  "contact_cfm",
                  "contact_stiffness",
                  "contact_damping",
                  "contact_spring_per",
                  "max_contacts",
                  "gravity",
                  "seed",
                  "cone",
                  "noslip_iterations",
                  "contact_timeconst",
                  "contact_dampratio",
                  "contact_dmin",
                  "contact_dmax"});
    no_children(e);
    once(e);
    PhysicsSettings& p = out_.physics;
    engine(e, p);
    p.step = e.number_or("step", p.step, Dimension::Time);
    if (p.step <= 0 || p.step > 0.02) e.fail_attr("step", "expected a time in (0, 20 ms]");
    using Solver = PhysicsSettings::Solver;
    const auto& solvers = EnumNames<Solver>::names;
    p.solver = static_cast<Solver>(e.choice_or("solver", {solvers[0], solvers[1], solvers[2]}, 1));
    p.iterations = e.integer_or("iterations", p.iterations, 1, 10000);
    p.sor = e.number_or("sor", p.sor);
    if (p.sor <= 0 || p.sor >= 2) e.fail_attr("sor", "expected a value in (0, 2)");
    p.erp = unit_interval(e, "erp", p.erp);
    p.cfm = non_negative(e, "cfm", p.cfm);
    p.contact_erp = unit_interval(e, "contact_erp", p.contact_erp);
    p.contact_cfm = non_negative(e, "contact_cfm", p.contact_cfm);
    contact_spring(e, p);
    p.contact_spring_per_body = e.choice_or("contact_spring_per", {"point", "body"}, 0) == 1;
    if (p.contact_spring_per_body && !e.has("contact_stiffness"))
      e.fail_attr("contact_spring_per", "expected contact_stiffness and contact_damping with it");
    p.max_contacts = e.integer_or("max_contacts", p.max_contacts, 1, 64);
    p.gravity = e.vector3_within("gravity", p.gravity, limits::kMaxGravity);
    p.seed = e.seed_or("seed", p.seed);
    parse_mujoco_options(e, p);
  }

  static constexpr const char* kOdeOnly[] = {"sor",
                                             "erp",
                                             "cfm",
                                             "contact_erp",
                                             "contact_cfm",
                                             "contact_stiffness",
                                             "contact_damping",
                                             "contact_spring_per",
                                             "max_contacts"};

  // engine="mujoco" needs the build to have it, and keeps to what MuJoCo can express here.
  static void engine(const XmlElement& e, PhysicsSettings& p) {
    p.file = e.file();
    p.line = e.line();
    if (e.choice_or("engine", {"ode", "mujoco"}, 0) == 0) return;
#ifndef STRIDE_HAVE_MUJOCO
    e.fail_attr("engine",
                "mujoco is not built into this stride (configure with libmujoco-dev "
                "installed and -DSTRIDE_MUJOCO=ON)");
#endif
    p.engine = PhysicsSettings::Engine::Mujoco;
    for (const char* ode_only : kOdeOnly)
      if (e.has(ode_only))
        e.fail_attr(ode_only,
                    "an ODE setting; engine=\"mujoco\" uses MuJoCo's own contact "
                    "model and takes step, solver, iterations, gravity, seed and its "
                    "cone, noslip_iterations and contact_timeconst/dampratio/dmin/dmax");
  }

  // Writes the attributes set over the scene into its element, dropping the ones they replace.
  void set_physics_over(const XmlElement& e) const {
    auto* raw = const_cast<XMLElement*>(e.raw());  // the parser owns the document
    for (const auto& [name, value] : physics_over_) {
      const bool spring = name == "contact_stiffness" || name == "contact_damping";
      const bool soft = name == "contact_erp" || name == "contact_cfm";
      for (const char* other : {"contact_stiffness", "contact_damping"})
        if (soft) raw->DeleteAttribute(other);
      for (const char* other : {"contact_erp", "contact_cfm"})
        if (spring) raw->DeleteAttribute(other);
      if (name == "engine" && value == "mujoco")  // the scene's ODE settings do not carry over
        for (const char* other : kOdeOnly) raw->DeleteAttribute(other);
      raw->SetAttribute(name.c_str(), value.c_str());
    }
  }

  // contact_stiffness [N/m] and contact_damping [N s/m] per contact point: the same soft contact
  // as contact_erp / contact_cfm, in physical units (either pair, not both).
  static void contact_spring(const XmlElement& e, PhysicsSettings& p) {
    const bool k = e.has("contact_stiffness"), c = e.has("contact_damping");
    if (!k && !c) return;
    if (k != c)
      e.fail_attr(k ? "contact_stiffness" : "contact_damping",
                  "expected contact_stiffness and contact_damping together");
    for (const char* a : {"contact_erp", "contact_cfm"})
      if (e.has(a))
        e.fail_attr(a,
                    "expected either contact_erp/contact_cfm or "
                    "contact_stiffness/contact_damping, not both");
    const double stiffness = e.number("contact_stiffness");
    if (!(stiffness > 0))  // number() already rejects non-finite text
      e.fail_attr("contact_stiffness", "expected a stiffness > 0 (N/m)");
    const double damping = e.number("contact_damping");
    if (!(damping >= 0)) e.fail_attr("contact_damping", "expected a damping >= 0 (N s/m)");
    const ContactSoftness soft = contact_softness(stiffness, damping, p.step);
    p.contact_erp = soft.erp;
    p.contact_cfm = soft.cfm;
  }

  static double unit_interval(const XmlElement& e, const char* a, double fallback) {
    const double v = e.number_or(a, fallback);
    if (v < 0 || v > 1) e.fail_attr(a, "expected a value in [0, 1]");
    return v;
  }
  static double non_negative(const XmlElement& e, const char* a, double fallback,
                             Dimension d = Dimension::None) {
    const double v = e.number_or(a, fallback, d);
    if (v < 0) e.fail_attr(a, "expected a value >= 0");
    return v;
  }
  static double positive(const XmlElement& e, const char* a, double fallback,
                         Dimension d = Dimension::None) {
    const double v = e.number_or(a, fallback, d);
    if (v <= 0) e.fail_attr(a, "expected a value > 0");
    return v;
  }

  void ground(const XmlElement& e) {
    e.allow_only({"enabled", "friction"});
    no_children(e);
    once(e);
    out_.ground.enabled = e.boolean_or("enabled", true);
    out_.ground.friction = non_negative(e, "friction", out_.ground.friction);
  }

  void box(const XmlElement& e) {
    e.allow_only({"name", "size", "xyz", "rpy", "friction"});
    no_children(e);
    StaticBox b;
    b.name = e.text_or("name", "box" + std::to_string(out_.boxes.size()));
    b.size = e.vector3_or("size", b.size, Dimension::Length);
    if ((b.size.array() <= 0).any()) e.fail_attr("size", "expected three lengths > 0");
    for (int i = 0; i < 3; ++i)
      e.check_within("size", b.size[i], 0, 2 * limits::kMaxPosition, Dimension::Length);
    b.pose = pose_from_xyz_rpy(
        e.vector3_within("xyz", Eigen::Vector3d::Zero(), limits::kMaxPosition, Dimension::Length),
        e.vector3_within("rpy", Eigen::Vector3d::Zero(), kMaxAngle, Dimension::Angle));
    b.friction = non_negative(e, "friction", b.friction);
    b.line = e.line();
    add_static_shapes(e, 1);
    out_.boxes.push_back(b);
  }

  // A slab whose top surface rises along +x (after yaw) at `slope`, starting at height 0 at xyz.
  void ramp(const XmlElement& e) {
    e.allow_only({"name", "xyz", "length", "width", "slope", "yaw", "thickness", "friction"});
    no_children(e);
    StaticBox b;
    b.name = e.text_or("name", "ramp" + std::to_string(out_.boxes.size()));
    const double length = positive(e, "length", 1.0, Dimension::Length);
    const double width = positive(e, "width", 1.0, Dimension::Length);
    const double thick = positive(e, "thickness", 0.05, Dimension::Length);
    for (const char* a : {"length", "width", "thickness"})
      e.number_within(a, 1, 0, 2 * limits::kMaxPosition, Dimension::Length);
    const double slope = e.number("slope", Dimension::Angle);
    if (std::abs(slope) >= 1.2) e.fail_attr("slope", "expected an angle below 1.2 rad");
    const double yaw = e.number_within("yaw", 0, -kMaxAngle, kMaxAngle, Dimension::Angle);
    const Eigen::Vector3d start =
        e.vector3_within("xyz", Eigen::Vector3d::Zero(), limits::kMaxPosition, Dimension::Length);
    b.size = Eigen::Vector3d(length, width, thick);
    // Top-surface centre lies half a length up the slope from the start edge.
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(-slope, Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
    b.pose = Eigen::Isometry3d::Identity();
    b.pose.linear() = r;
    b.pose.translation() = start + r * Eigen::Vector3d(length / 2, 0, -thick / 2);
    b.friction = non_negative(e, "friction", b.friction);
    b.line = e.line();
    add_static_shapes(e, 1);
    out_.boxes.push_back(b);
  }

  void camera(const XmlElement& e) {
    e.allow_only({"name", "xyz", "look_at", "fov", "width", "height"});
    no_children(e);
    SceneCamera c;
    c.name = e.text("name");
    for (const SceneCamera& other : out_.cameras)
      if (other.name == c.name) e.fail_attr("name", "a camera '" + c.name + "' exists already");
    c.eye = e.vector3_within("xyz", c.eye, limits::kMaxPosition, Dimension::Length);
    c.look_at = e.vector3_within("look_at", c.look_at, limits::kMaxPosition, Dimension::Length);
    if ((c.look_at - c.eye).norm() < 1e-6) e.fail_attr("look_at", "expected a point away from xyz");
    c.fov = e.number_or("fov", c.fov, Dimension::Angle);
    if (!(c.fov > 0.05 && c.fov < 3.0)) e.fail_attr("fov", "expected an angle in (0.05, 3) rad");
    c.width = e.integer_or("width", c.width, 16, 4096);
    c.height = e.integer_or("height", c.height, 16, 4096);
    c.line = e.line();
    out_.cameras.push_back(c);
  }

  void light(const XmlElement& e) {
    e.allow_only({"direction", "intensity"});
    no_children(e);
    if (out_.lights.size() >= 8) e.fail("at most 8 lights");
    SceneLight l;
    l.direction = e.vector3_or("direction", l.direction);
    if (l.direction.norm() < 1e-9) e.fail_attr("direction", "expected a non-zero vector");
    l.intensity = e.number_or("intensity", l.intensity);
    if (!(l.intensity >= 0 && l.intensity <= 1))
      e.fail_attr("intensity", "expected a value in [0, 1]");
    out_.lights.push_back(l);
  }

  void uneven(const XmlElement& e) {
    e.allow_only({"name", "centre", "size", "cell", "height", "tilt", "friction", "seed"});
    no_children(e);
    UnevenPatch u;
    u.name = e.text_or("name", "uneven" + std::to_string(out_.uneven.size()));
    u.centre = e.vector2_within("centre", u.centre, limits::kMaxPosition, Dimension::Length);
    u.size = e.vector2_within("size", u.size, 2 * limits::kMaxPosition, Dimension::Length);
    if ((u.size.array() <= 0).any()) e.fail_attr("size", "expected two lengths > 0");
    u.cell = positive(e, "cell", u.cell, Dimension::Length);
    if (u.size.x() / u.cell * u.size.y() / u.cell > 200000)
      e.fail_attr("cell", "too many tiles (more than 200000); use a larger cell");
    u.max_height = non_negative(e, "height", u.max_height, Dimension::Length);
    e.number_within("height", 0, 0, limits::kMaxLength, Dimension::Length);
    u.max_tilt = non_negative(e, "tilt", u.max_tilt, Dimension::Angle);
    if (u.max_tilt > 0.5) e.fail_attr("tilt", "expected at most 0.5 rad");
    u.friction = non_negative(e, "friction", u.friction);
    u.seed = e.seed_or("seed", 0);
    add_static_shapes(e, uneven_tile_count(u));
    out_.uneven.push_back(u);
  }

  void robot(const XmlElement& e) {
    e.allow_only({"name", "urdf", "devices", "xyz", "rpy", "fixed", "stiffness", "fall_tilt",
                  "fall_height", "period"});
    if (out_.robots.size() >= static_cast<std::size_t>(scene_limits::kMaxRobots))
      e.fail("more than " + std::to_string(scene_limits::kMaxRobots) + " robots in one scene");
    RobotPlacement r;
    r.file = e.file();
    r.line = e.line();
    r.name = e.text_or("name", "robot" + std::to_string(out_.robots.size()));
    for (const auto& other : out_.robots)
      if (other.name == r.name)
        e.fail_attr("name", "a robot named '" + r.name + "' already exists");
    r.urdf = resolve_from(e, e.text("urdf"));
    r.devices = e.has("devices") ? resolve_from(e, e.text("devices")) : std::string();
    if (e.has("xyz")) placement_xyz(e, r);
    r.rpy = e.vector3_within("rpy", r.rpy, kMaxAngle, Dimension::Angle);
    r.fixed_base = e.boolean_or("fixed", false);
    r.stiffness = e.number_or("stiffness", 1.0);
    if (r.stiffness < 0 || r.stiffness > 1) e.fail_attr("stiffness", "expected a value in [0, 1]");
    if (e.has("period")) {
      r.period = positive(e, "period", 0.01, Dimension::Time);
      e.check_within("period", r.period, 0, 10, Dimension::Time);
    }
    r.fall_tilt = positive(e, "fall_tilt", r.fall_tilt, Dimension::Angle);
    r.fall_height = non_negative(e, "fall_height", r.fall_height, Dimension::Length);
    robot_children(e, r);
    out_.robots.push_back(std::move(r));
  }

  // xyz="x y z" with z a length or 'auto' (lowest collision point on the floor).
  static void placement_xyz(const XmlElement& e, RobotPlacement& r) {
    std::istringstream in(e.text("xyz"));
    std::string xs, ys, zs, extra;
    in >> xs >> ys >> zs >> extra;
    if (zs.empty() || !extra.empty())
      e.fail_attr("xyz", "expected 'x y z' lengths, z may be 'auto'");
    try {
      r.xyz.x() = parse_quantity(xs, Dimension::Length);
      r.xyz.y() = parse_quantity(ys, Dimension::Length);
      r.auto_height = zs == "auto";
      if (!r.auto_height) r.xyz.z() = parse_quantity(zs, Dimension::Length);
    } catch (const std::invalid_argument& ex) {
      e.fail_attr("xyz", ex.what());
    }
    for (int i = 0; i < 3; ++i)
      e.check_within("xyz", r.xyz[i], -limits::kMaxPosition, limits::kMaxPosition,
                     Dimension::Length);
  }

  void robot_children(const XmlElement& e, RobotPlacement& r) {
    std::map<std::string, std::string> seen;  // "<joints>", "motor pitch", ... -> "file:line"
    const auto once = [&](const XmlElement& c, const std::string& key, const std::string& what) {
      const auto [it, fresh] = seen.emplace(key, c.file() + ":" + std::to_string(c.line()));
      if (!fresh)
        c.fail((what.empty() ? "" : what + " ") + "given twice in one <robot> (first at " +
               it->second + ")");
    };
    for (const XMLElement* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement()) {
      XmlElement child(c, e.file());
      if (child.name() == "include")
        robot_include(child, r, once);
      else
        robot_child(child, r, once);
    }
  }

  using Once = std::function<void(const XmlElement&, const std::string&, const std::string&)>;

  // <include file="robot-id.xml"/> in a <robot> (robot_override_file.hpp).
  void robot_include(const XmlElement& e, RobotPlacement& r, const Once& once) {
    if (++robot_includes_ > kMaxRobotIncludes)
      e.fail("more than " + std::to_string(kMaxRobotIncludes) + " robot includes in one scene");
    for (const XmlElement& child : robot_override_children(e, override_files_))
      robot_child(child, r, once);
  }

  void robot_child(const XmlElement& child, RobotPlacement& r, const Once& once) {
    const std::string_view n = child.name();
    if (n == "joints" || n == "sensors" || n == "controller" || n == "calibration" || n == "imu")
      once(child, std::string(n), "");
    if ((n == "motor" || n == "servo" || n == "calibration" || n == "imu") && r.devices.empty())
      child.fail("<" + std::string(n) + "> changes the device file, and there is none");
    if (n == "joints") {
      // Attributes are joint names; they are checked against the URDF when the world is built.
      r.joints_line = child.line();
      for (const tinyxml2::XMLAttribute* a = child.raw()->FirstAttribute(); a; a = a->Next())
        r.joints[a->Name()] = child.number_within(a->Name(), 0, -limits::kMaxJointRange,
                                                  limits::kMaxJointRange, Dimension::Angle);
    } else if (n == "sensors") {
      child.allow_only({"noise", "delay", "quantise"});
      r.sensors.noise = child.boolean_or("noise", true);
      r.sensors.delay = child.boolean_or("delay", true);
      r.sensors.quantise = child.boolean_or("quantise", true);
    } else if (n == "controller") {
      r.has_controller = true;
      r.controller = parse_controller(child);
    } else if (n == "motor") {
      r.motors.push_back(motor_override(child));
      once(child, "motor " + r.motors.back().name, "name '" + r.motors.back().name + "'");
    } else if (n == "servo") {
      r.servos.push_back(servo_override(child));
      once(child, "servo " + r.servos.back().joint, "joint '" + r.servos.back().joint + "'");
    } else if (n == "calibration") {
      r.calibration = calibration_spread(child);
    } else if (n == "imu") {
      r.gyro_bias = gyro_bias_override(child);
    } else {
      child.fail(
          "unknown element in <robot> (expected joints, sensors, controller, motor, servo, "
          "calibration, imu or include)");
    }
  }

  void push(const XmlElement& e) {
    e.allow_only({"robot", "body", "force", "at", "start", "duration"});
    no_children(e);
    TimedPush p;
    p.robot = e.text("robot");
    p.body = e.text("body");
    p.force = e.vector3_within("force", p.force, limits::kMaxForce, Dimension::Force);
    if (!e.has("force")) e.fail("missing attribute 'force'");
    p.at = e.vector3_within("at", p.at, limits::kMaxLength, Dimension::Length);
    p.start = non_negative(e, "start", 0, Dimension::Time);
    e.number_within("start", 0, 0, limits::kMaxDuration, Dimension::Time);
    p.duration = positive(e, "duration", 0.1, Dimension::Time);
    e.number_within("duration", 0, 0, limits::kMaxDuration, Dimension::Time);
    p.file = e.file();
    p.line = e.line();
    out_.pushes.push_back(p);
  }

  SceneDescription& out_;
  bool law_included_ = false;                     // the <contact> so far came from an included file
  std::map<std::string, std::string> seen_once_;  // element name -> "file:line" of the first
  long static_shapes_ = 0;
  PhysicsAttributes physics_over_;
  bool physics_seen_ = false;
  ReplacedAttribute replaced_;
  UnstatedFriction unstated_{true, {}, {}};  // no <ground>: the default ground states none
  int robot_includes_ = 0;
  RobotOverrideFiles override_files_;
  IncludeWalk walk_{[this](const XmlElement& e) { scene_root(e); },
                    [this](const XmlElement& e) { element(e); }};
};

// Checks that need the whole scene: pushes name robots that exist.
void check_references(const SceneDescription& s) {
  for (const TimedPush& p : s.pushes) {
    bool found = false;
    for (const auto& r : s.robots) found = found || r.name == p.robot;
    if (!found)
      throw error_at(p.file, p.line,
                     "<push>: attribute 'robot': no robot named '" + p.robot + "' in the scene");
  }
}

}  // namespace

SceneDescription parse_scene_file(const std::string& path) {
  return parse_scene_file(path, {});
}

SceneDescription parse_scene_file(const std::string& given, const PhysicsAttributes& physics_over) {
  const std::string path = find_input(given);  // a shipped scene from any working directory
  SceneDescription s;
  s.file = path;
  try {
    Parser p(s, physics_over);
    p.parse_file(path);
    p.physics_over_defaults();
    p.finish();
    check_references(s);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(e.what());
  }
  return s;
}

PhysicsAttributes parse_physics_setting(const std::string& text) {
  for (char c : text)  // the error below repeats the text: it must stay one printable line
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      throw Error("physics setting: expected printable attribute=value[,attribute=value...] text");
  const std::string where = "physics setting '" + text + "'";
  PhysicsAttributes attrs;
  std::stringstream list(text);
  std::string xml = "<scene><physics";
  for (std::string item; std::getline(list, item, ',');) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw Error(where + ": expected attribute=value[,attribute=value...], got '" + item + "'");
    const std::string name = item.substr(0, eq), value = item.substr(eq + 1);
    if (name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_") != std::string::npos ||
        value.find_first_of("\"<>&") != std::string::npos)
      throw Error(where + ": '" + item + "' is not a <physics> attribute and value");
    attrs.emplace_back(name, value);
    xml += " " + name + "=\"" + value + "\"";
  }
  if (attrs.empty()) throw Error(where + ": expected attribute=value[,attribute=value...]");
  parse_scene_text(xml + "/></scene>", where);  // each value checked as the scene's would be
  // Iterations or over-relaxation name the iterative solver, also over a scene that states the
  // exact one (as every walking scene does).
  const auto named = [&](const char* a) {
    return std::any_of(attrs.begin(), attrs.end(), [&](const auto& kv) { return kv.first == a; });
  };
  if ((named("iterations") || named("sor")) && !named("solver"))
    attrs.insert(attrs.begin(), {"solver", "iterative"});
  return attrs;
}

SceneDescription parse_scene_text(const std::string& text, const std::string& virtual_path) {
  SceneDescription s;
  s.file = virtual_path;
  Parser p(s);
  p.parse_text(text, virtual_path);
  p.finish();
  check_references(s);
  return s;
}

}  // namespace stride::sim
