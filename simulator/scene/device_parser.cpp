#include <algorithm>
#include <map>
#include <numbers>
#include <sstream>
#include <vector>

#include "robot/core/error.hpp"
#include "robot/core/input_file.hpp"
#include "robot/core/physical_limits.hpp"
#include "robot/core/xml_element.hpp"
#include "robot/core/xml_error.hpp"
#include "simulator/scene/device_description.hpp"
#include "simulator/scene/device_parser.hpp"

namespace stride::sim {
namespace {

using tinyxml2::XMLElement;

// Device numbers beyond this (in their SI unit; forces and torques: limits::kMaxForce) are no
// device: they would only reach the physics as overflow.
constexpr double kMaxDeviceNumber = 1e6;

double non_negative(const XmlElement& e, const char* a, double fallback,
                    Dimension d = Dimension::None, double most = kMaxDeviceNumber) {
  const double v = e.number_or(a, fallback, d);
  if (v < 0) e.fail_attr(a, "expected a value >= 0");
  if (e.has(a)) e.check_within(a, v, 0, most, d);
  return v;
}

double positive(const XmlElement& e, const char* a, double fallback, Dimension d = Dimension::None,
                double most = kMaxDeviceNumber) {
  const double v = e.number_or(a, fallback, d);
  if (v <= 0) e.fail_attr(a, "expected a value > 0");
  if (e.has(a)) e.check_within(a, v, 0, most, d);
  return v;
}

// The first element of each kind (or named thing) by "file:line", so a second names both.
class SeenOnce {
 public:
  void check(const XmlElement& e, const std::string& key, const std::string& what) {
    const auto [it, fresh] = seen_.emplace(key, e.file() + ":" + std::to_string(e.line()));
    if (!fresh)
      e.fail((what.empty() ? "" : what + " ") + "given twice (first at " + it->second + ")");
  }

 private:
  std::map<std::string, std::string> seen_;
};

// The <motor> attributes besides its name, with their units and where they go.
struct MotorNumber {
  const char* attr;
  Dimension dimension;
  double MotorSpec::*field;
};
constexpr MotorNumber kMotorNumbers[] = {
    {"ratio", Dimension::None, &MotorSpec::ratio},
    {"stall_torque", Dimension::None, &MotorSpec::stall_torque},
    {"no_load_speed", Dimension::Angle, &MotorSpec::no_load_speed},
    {"torque_constant", Dimension::None, &MotorSpec::torque_constant},
    {"gain", Dimension::None, &MotorSpec::gain},
    {"spring", Dimension::None, &MotorSpec::spring},
    {"damping", Dimension::None, &MotorSpec::damping},
    {"integral", Dimension::None, &MotorSpec::integral},
    {"backlash", Dimension::Angle, &MotorSpec::backlash},
};

// The <motor> attributes present on e (all > 0), by name; e may have `others` besides.
std::map<std::string, double> motor_numbers(const XmlElement& e,
                                            std::vector<std::string_view> others = {"name"}) {
  for (const MotorNumber& n : kMotorNumbers) others.push_back(n.attr);
  e.allow_only(others);
  std::map<std::string, double> values;
  for (const MotorNumber& n : kMotorNumbers)
    if (e.has(n.attr)) values[n.attr] = positive(e, n.attr, 1.0, n.dimension);
  return values;
}

void set_motor_numbers(MotorSpec& m, const std::map<std::string, double>& values) {
  for (const MotorNumber& n : kMotorNumbers)
    if (auto it = values.find(n.attr); it != values.end()) m.*n.field = it->second;
}

// What no single attribute shows; empty when the motor is usable.
std::string motor_problem(const MotorSpec& m) {
  if (m.damping > 0 && m.spring <= 0)
    return "damping is only for a spring (the velocity servo has no damping setting)";
  if (m.integral > 0 && m.spring <= 0)
    return "integral is only for a spring (the velocity servo has no integral setting)";
  if (m.backlash > 0 && m.spring > 0)
    return "backlash is only for the velocity servo, not a spring";
  return {};
}

// m with a scene's attribute changes; throws at the scene's file:line, prefixed with `where`,
// when the result is inconsistent.
MotorSpec changed_motor(const MotorSpec& m, const std::map<std::string, double>& values,
                        const std::string& file, int line, const std::string& where) {
  MotorSpec changed = m;
  set_motor_numbers(changed, values);
  if (const std::string problem = motor_problem(changed); !problem.empty())
    throw error_at(file, line, where + problem);
  return changed;
}

MotorSpec motor(const XmlElement& e) {
  MotorSpec m;
  m.name = e.text("name");
  set_motor_numbers(m, motor_numbers(e));
  if (const std::string problem = motor_problem(m); !problem.empty()) e.fail(problem);
  return m;
}

ImuSpec imu(const XmlElement& e) {
  e.allow_only({"link", "accelerometer", "gyroscope", "accel_noise", "gyro_noise", "angle_noise",
                "gyro_bias", "accel_bias", "accel_range", "gyro_range", "delay"});
  ImuSpec s;
  s.link = e.text_or("link", s.link);
  s.accelerometer_at =
      e.vector3_within("accelerometer", s.accelerometer_at, limits::kMaxLength, Dimension::Length);
  s.gyroscope_at =
      e.vector3_within("gyroscope", s.gyroscope_at, limits::kMaxLength, Dimension::Length);
  s.accel_noise = non_negative(e, "accel_noise", 0);
  s.gyro_noise = non_negative(e, "gyro_noise", 0, Dimension::Angle);
  s.angle_noise = non_negative(e, "angle_noise", 0, Dimension::Angle);
  s.gyro_bias = e.vector3_within("gyro_bias", s.gyro_bias, kMaxDeviceNumber, Dimension::Angle);
  s.accel_bias = e.vector3_within("accel_bias", s.accel_bias, kMaxDeviceNumber);
  s.accel_range = positive(e, "accel_range", s.accel_range);
  s.gyro_range = positive(e, "gyro_range", s.gyro_range, Dimension::Angle);
  s.delay_frames = e.integer_or("delay", 0, 0, 100);
  return s;
}

FsrSpec fsr(const XmlElement& e) {
  e.allow_only({"link", "sole_z", "noise", "max_force"});
  FsrSpec f;
  f.link = e.text("link");
  f.sole_z = e.number("sole_z", Dimension::Length);
  e.check_within("sole_z", f.sole_z, -limits::kMaxLength, limits::kMaxLength, Dimension::Length);
  f.noise = non_negative(e, "noise", 0, Dimension::Force, limits::kMaxForce);
  f.max_force = positive(e, "max_force", f.max_force, Dimension::Force, limits::kMaxForce);
  int n = 0;
  for (const XMLElement* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement()) {
    XmlElement s(c, e.file());
    if (s.name() != "sensor") s.fail("unknown element in <fsr> (expected sensor)");
    s.allow_only({"name", "x", "y"});
    if (n == 4) s.fail("an <fsr> has exactly four sensors (FL, FR, RL, RR)");
    f.names[n] = s.text("name");
    f.positions[n] =
        Eigen::Vector2d(s.number("x", Dimension::Length), s.number("y", Dimension::Length));
    for (int k = 0; k < 2; ++k)
      s.check_within(k ? "y" : "x", f.positions[n][k], -limits::kMaxLength, limits::kMaxLength,
                     Dimension::Length);
    ++n;
  }
  if (n != 4) e.fail("an <fsr> has exactly four <sensor> children (FL, FR, RL, RR)");
  return f;
}

}  // namespace

DeviceDescription load_device_file(const std::string& path) {
  const std::string text = read_input_file(path, kMaxTextInputBytes, "device file");
  tinyxml2::XMLDocument doc;
  if (doc.Parse(text.c_str(), text.size()) != tinyxml2::XML_SUCCESS)
    throw error_at(path, doc.ErrorLineNum(), xml_error_text(doc));
  const XMLElement* root = doc.RootElement();
  if (!root || std::string_view(root->Name()) != "devices")
    throw error_at(path, root ? root->GetLineNum() : 1, "expected <devices> as the root element");
  DeviceDescription d;
  d.file = path;
  XmlElement r(root, d.file);
  r.allow_only({"period"});
  d.period = positive(r, "period", d.period, Dimension::Time, 10);
  SeenOnce seen;
  for (const XMLElement* c = root->FirstChildElement(); c; c = c->NextSiblingElement()) {
    XmlElement e(c, d.file);
    const std::string_view n = e.name();
    if (n == "encoder" || n == "imu") seen.check(e, std::string(n), "");
    if (n == "motor") {
      d.motors.push_back(motor(e));
      seen.check(e, "motor " + d.motors.back().name, "name '" + d.motors.back().name + "'");
    } else if (n == "servo") {
      e.allow_only({"joint", "motor", "offset"});
      ServoSpec s;
      s.joint = e.text("joint");
      seen.check(e, "servo " + s.joint, "joint '" + s.joint + "'");
      s.offset = e.number_within("offset", 0.0, -0.5, 0.5, Dimension::Angle);
      const std::string m = e.text("motor");
      for (size_t i = 0; i < d.motors.size(); ++i)
        if (d.motors[i].name == m) s.motor = static_cast<int>(i);
      if (s.motor < 0) e.fail_attr("motor", "no <motor name=\"" + m + "\"> defined above");
      d.servos.push_back(s);
    } else if (n == "encoder") {
      e.allow_only({"bits", "noise"});
      d.encoder.bits = e.integer_or("bits", d.encoder.bits, 1, 32);
      d.encoder.noise = non_negative(e, "noise", 0, Dimension::Angle);
    } else if (n == "imu") {
      d.imu = imu(e);
    } else if (n == "fsr") {
      d.fsrs.push_back(fsr(e));
      seen.check(e, "fsr " + d.fsrs.back().link, "link '" + d.fsrs.back().link + "'");
    } else {
      e.fail("unknown element (expected motor, servo, encoder, imu or fsr)");
    }
  }
  return d;
}

MotorOverride motor_override(const XmlElement& e) {
  MotorOverride o;
  o.name = e.text("name");
  o.values = motor_numbers(e);
  if (o.values.empty()) e.fail("expected at least one motor attribute to change");
  o.file = e.file();
  o.line = e.line();
  return o;
}

ServoOverride servo_override(const XmlElement& e) {
  ServoOverride o;
  o.motor = motor_numbers(e, {"joint", "offset"});
  o.joint = e.text("joint");
  if (e.has("offset")) o.offset = e.number_within("offset", 0, -0.5, 0.5, Dimension::Angle);
  if (!o.offset && o.motor.empty())
    e.fail(
        "expected an offset or a motor attribute to change (e.g. offset=\"3deg\", spring=\"400\")");
  o.file = e.file();
  o.line = e.line();
  return o;
}

CalibrationSpread calibration_spread(const XmlElement& e) {
  e.allow_only({"sd", "joints"});
  CalibrationSpread c;
  c.sd = e.number("sd", Dimension::Angle);
  constexpr double kLargest = 10 * std::numbers::pi / 180;  // beyond this it is no calibration
  if (!(c.sd > 0) || c.sd > kLargest) e.fail_attr("sd", "expected an angle in (0, 10deg]");
  if (e.has("joints")) {
    std::string list = e.text("joints");
    std::replace(list.begin(), list.end(), ',', ' ');
    std::istringstream in(list);
    for (std::string j; in >> j;) {
      if (std::find(c.joints.begin(), c.joints.end(), j) != c.joints.end())
        e.fail_attr("joints", "'" + j + "' is listed twice");
      c.joints.push_back(j);
    }
    if (c.joints.empty()) e.fail_attr("joints", "expected joint names (or leave it out: the legs)");
  }
  c.file = e.file();
  c.line = e.line();
  return c;
}

Eigen::Vector3d gyro_bias_override(const XmlElement& e) {
  e.allow_only({"gyro_bias"});
  if (e.raw()->FirstChildElement()) e.fail("unexpected child element of <imu>");
  if (!e.has("gyro_bias")) e.fail("expected gyro_bias=\"x y z\" (e.g. \"-18deg -18deg 0\")");
  constexpr double kLargest = 10;  // rad/s: beyond any gyro's range
  return e.vector3_within("gyro_bias", Eigen::Vector3d::Zero(), kLargest, Dimension::Angle);
}

void apply_servo_override(DeviceDescription& devices, const ServoOverride& override_) {
  const std::string where = "<servo joint=\"" + override_.joint + "\">: ";
  for (ServoSpec& s : devices.servos) {
    if (s.joint != override_.joint) continue;
    if (!override_.motor.empty()) {
      // The joint gets its own copy of its motor, so the joints sharing the motor keep theirs;
      // checked before anything changes.
      MotorSpec own = changed_motor(devices.motors[s.motor], override_.motor, override_.file,
                                    override_.line, where);
      own.name += "@" + s.joint;
      devices.motors.push_back(own);
      s.motor = static_cast<int>(devices.motors.size() - 1);
    }
    if (override_.offset) s.offset = *override_.offset;
    return;
  }
  throw error_at(override_.file, override_.line,
                 where + "no servo for that joint in " + devices.file);
}

void apply_motor_override(DeviceDescription& devices, const MotorOverride& override_) {
  for (MotorSpec& m : devices.motors) {
    if (m.name != override_.name) continue;
    m = changed_motor(m, override_.values, override_.file, override_.line,
                      "<motor name=\"" + m.name + "\">: ");
    return;
  }
  throw error_at(override_.file, override_.line,
                 "<motor name=\"" + override_.name + "\">: no such motor in " + devices.file);
}

}  // namespace stride::sim
