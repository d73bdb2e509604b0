#include "console/identify/identify_params.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "behaviours/identify/excitation.hpp"
#include "robot/core/error.hpp"
#include "robot/hal/joint_id.hpp"

namespace stride::identify {
namespace {

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::string word;
  std::istringstream in(text);
  while (std::getline(in, word, ','))
    if (!word.empty()) out.push_back(word);
  return out;
}

}  // namespace

std::string_view kind_name(ParamKind k) {
  return enum_name(k);
}

ParamChoice parse_param_list(const std::string& text) {
  static const std::map<std::string, std::string> unmodelled = {
      {"delay", "the simulated servo has no command delay"},
      {"friction", "the simulated joints have no friction"},
      {"backlash", "not fitted yet (the gear-play servo is a different model from the plain one)"},
      {"offset",
       "not fitted yet: the logged joint angles do not resolve it (the servo brings the encoder "
       "reading to the command whatever the offset), and fits on held logs moved it by noise"},
      {"fsr_scale", "the simulated FSRs have no scale error"},
      {"fsr_offset", "the simulated FSRs have no offset"}};
  const std::string expected = "expected a comma-separated list of gain, torque, gyro_bias";
  ParamChoice c;
  const auto words = split(text);
  if (words.empty()) throw Error("stride identify: --params: empty list; " + expected);
  for (const std::string& w : words) {
    const std::optional<ParamKind> k = enum_from_name<ParamKind>(w);
    const bool repeated =
        (k && std::ranges::count(c.kinds, *k) > 0) || (w == "gyro_bias" && c.gyro_bias);
    if (repeated) throw Error("stride identify: --params: '" + w + "' given twice");
    if (k) {
      c.kinds.push_back(*k);
    } else if (w == "gyro_bias") {
      c.gyro_bias = true;
    } else if (const auto it = unmodelled.find(w); it != unmodelled.end()) {
      throw Error("stride identify: --params: '" + w + "' cannot be identified: " + it->second +
                  "; " + expected);
    } else {
      throw Error("stride identify: --params: unknown parameter '" + w.substr(0, 40) + "'; " +
                  expected);
    }
  }
  return c;
}

std::vector<int> parse_joint_list(const std::string& text) {
  const auto& legs = behaviours::kExcitedLegJoints;
  if (text.empty()) return {legs.begin(), legs.end()};
  std::vector<int> out;
  for (const std::string& w : split(text)) {
    const auto id = hal::joint_from_name(w);
    const int i = id ? hal::index(*id) : -1;
    if (std::ranges::count(legs, i) == 0)
      throw Error("stride identify: --joints: '" + w.substr(0, 40) +
                  "' is not a leg joint (expected LHipRoll ... LAnkleRoll, RHipRoll ... "
                  "RAnkleRoll; HipYawPitch is one motor for both legs)");
    if (std::ranges::count(out, i) > 0)
      throw Error("stride identify: --joints: '" + w + "' given twice");
    out.push_back(i);
  }
  if (out.empty()) throw Error("stride identify: --joints: empty list");
  return out;
}

std::string Param::name() const {
  return std::string(hal::kJointNames[joint]) + "." + std::string(kind_name(kind));
}

std::vector<Param> make_params(const ParamChoice& choice, const std::vector<int>& joints,
                               const sim::DeviceDescription& devices) {
  std::vector<Param> out;
  for (int j : joints) {
    const std::string name(hal::kJointNames[j]);
    const auto s = std::ranges::find(devices.servos, name, &sim::ServoSpec::joint);
    if (s == devices.servos.end())
      throw Error(devices.file + ": no servo for joint '" + name + "' (identify fits servos)");
    const sim::MotorSpec& m = devices.motors[s->motor];
    for (ParamKind k : choice.kinds) {
      switch (k) {
        case ParamKind::gain:
          out.push_back({k, j, m.gain, 0.2 * m.gain, 5 * m.gain, 0.1 * m.gain, 0.1 * m.gain});
          break;
        case ParamKind::torque:
          out.push_back({k, j, m.stall_torque, 0.2 * m.stall_torque, 3 * m.stall_torque,
                         0.1 * m.stall_torque, 0.1 * m.stall_torque});
          break;
      }
    }
  }
  return out;
}

std::vector<sim::ServoOverride> servo_overrides(const std::vector<Param>& params,
                                                const std::vector<double>& values) {
  std::map<int, sim::ServoOverride> by_joint;
  for (std::size_t i = 0; i < params.size(); ++i) {
    sim::ServoOverride& o = by_joint[params[i].joint];
    o.joint = std::string(hal::kJointNames[params[i].joint]);
    o.file = "stride identify";
    switch (params[i].kind) {
      case ParamKind::gain:
        o.motor["gain"] = values[i];
        break;
      case ParamKind::torque:
        o.motor["stall_torque"] = values[i];
        break;
    }
  }
  std::vector<sim::ServoOverride> out;
  for (auto& [j, o] : by_joint) out.push_back(std::move(o));
  return out;
}

}  // namespace stride::identify
