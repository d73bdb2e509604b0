#include <fstream>
#include <sstream>

#include "robot/core/error.hpp"
#include "robot/core/xml_error.hpp"
#include "simulator/devices/device_description.hpp"
#include "simulator/scene/xml_element.hpp"

namespace stride::sim {
namespace {

using tinyxml2::XMLElement;

double non_negative(const XmlElement& e, const char* a, double fallback,
                    Dimension d = Dimension::None) {
  const double v = e.number_or(a, fallback, d);
  if (v < 0) e.fail_attr(a, "expected a value >= 0");
  return v;
}

double positive(const XmlElement& e, const char* a, double fallback,
                Dimension d = Dimension::None) {
  const double v = e.number_or(a, fallback, d);
  if (v <= 0) e.fail_attr(a, "expected a value > 0");
  return v;
}

MotorSpec motor(const XmlElement& e) {
  e.allow_only({"name", "ratio", "stall_torque", "no_load_speed", "torque_constant", "gain",
                "spring", "damping"});
  MotorSpec m;
  m.name = e.text("name");
  m.ratio = positive(e, "ratio", m.ratio);
  m.stall_torque = positive(e, "stall_torque", m.stall_torque);
  m.no_load_speed = positive(e, "no_load_speed", m.no_load_speed, Dimension::Angle);
  m.torque_constant = positive(e, "torque_constant", m.torque_constant);
  m.gain = positive(e, "gain", m.gain);
  if (e.has("spring")) {
    m.spring = positive(e, "spring", m.spring);
    // A voltage-driven DC motor brakes with its back-EMF: stall torque over no-load speed.
    m.damping = positive(e, "damping", m.stall_torque / m.no_load_speed);
  } else if (e.has("damping")) {
    e.fail_attr("damping", "only with a spring (the velocity servo has no damping setting)");
  }
  return m;
}

ImuSpec imu(const XmlElement& e) {
  e.allow_only({"link", "accelerometer", "gyroscope", "accel_noise", "gyro_noise", "angle_noise",
                "gyro_bias", "accel_bias", "accel_range", "gyro_range", "delay"});
  ImuSpec s;
  s.link = e.text_or("link", s.link);
  s.accelerometer_at = e.vector3_or("accelerometer", s.accelerometer_at, Dimension::Length);
  s.gyroscope_at = e.vector3_or("gyroscope", s.gyroscope_at, Dimension::Length);
  s.accel_noise = non_negative(e, "accel_noise", 0);
  s.gyro_noise = non_negative(e, "gyro_noise", 0, Dimension::Angle);
  s.angle_noise = non_negative(e, "angle_noise", 0, Dimension::Angle);
  s.gyro_bias = e.vector3_or("gyro_bias", s.gyro_bias, Dimension::Angle);
  s.accel_bias = e.vector3_or("accel_bias", s.accel_bias);
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
  f.noise = non_negative(e, "noise", 0, Dimension::Force);
  f.max_force = positive(e, "max_force", f.max_force, Dimension::Force);
  int n = 0;
  for (const XMLElement* c = e.raw()->FirstChildElement(); c; c = c->NextSiblingElement()) {
    XmlElement s(c, e.file());
    if (s.name() != "sensor") s.fail("unknown element in <fsr> (expected sensor)");
    s.allow_only({"name", "x", "y"});
    if (n == 4) s.fail("an <fsr> has exactly four sensors (FL, FR, RL, RR)");
    f.names[n] = s.text("name");
    f.positions[n] =
        Eigen::Vector2d(s.number("x", Dimension::Length), s.number("y", Dimension::Length));
    ++n;
  }
  if (n != 4) e.fail("an <fsr> has exactly four <sensor> children (FL, FR, RL, RR)");
  return f;
}

}  // namespace

DeviceDescription load_device_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ":0: cannot open device file");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
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
  d.period = positive(r, "period", d.period, Dimension::Time);
  for (const XMLElement* c = root->FirstChildElement(); c; c = c->NextSiblingElement()) {
    XmlElement e(c, d.file);
    const std::string_view n = e.name();
    if (n == "motor") {
      d.motors.push_back(motor(e));
    } else if (n == "servo") {
      e.allow_only({"joint", "motor"});
      ServoSpec s;
      s.joint = e.text("joint");
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
    } else {
      e.fail("unknown element (expected motor, servo, encoder, imu or fsr)");
    }
  }
  return d;
}

}  // namespace stride::sim
