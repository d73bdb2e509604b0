#pragma once
// The parameters `stride identify` can fit, per joint: what they are in the simulated servo
// (simulator/devices), their bounds and finite-difference steps, and the `--params` list.
#include <string>
#include <vector>

#include "robot/framework/enum_names.hpp"
#include "simulator/scene/device_description.hpp"

namespace stride::identify {

// gain: the velocity servo's 1/s; torque: the motor's stall torque (the torque limit at
// stiffness 1).
enum class ParamKind { gain, torque };

}  // namespace stride::identify

namespace stride {
template <>
struct EnumNames<identify::ParamKind> {
  static constexpr std::string_view type_name = "ParamKind";
  static constexpr std::array<std::string_view, 2> names{"gain", "torque"};
};
}  // namespace stride

namespace stride::identify {

struct ParamChoice {
  std::vector<ParamKind> kinds;  // per joint
  bool gyro_bias = false;
};

// "gain,torque,gyro_bias" (any order, no repeats). Throws stride::Error, one line, for an unknown
// name, naming what the simulated plant does not model (delay, friction, fsr, backlash, offset) as
// such.
ParamChoice parse_param_list(const std::string& text);
// "LHipPitch,RKneePitch" (LoLA names of leg joints other than HipYawPitch); empty: all ten.
std::vector<int> parse_joint_list(const std::string& text);

std::string_view kind_name(ParamKind k);

struct Param {
  ParamKind kind;
  int joint;  // LoLA index
  double nominal, lower, upper;
  double step;    // finite-difference step
  double wanted;  // the resolution a useful fit needs: wider 95% intervals are not identified
  std::string name() const;  // "LKneePitch.gain"
};

// The parameters of `kinds` on `joints`, nominal values from the robot's device file. Throws
// stride::Error naming the file when a joint has no servo there.
std::vector<Param> make_params(const ParamChoice& choice, const std::vector<int>& joints,
                               const sim::DeviceDescription& devices);

// The servo overrides that give the robot `values` (one per parameter, in order).
std::vector<sim::ServoOverride> servo_overrides(const std::vector<Param>& params,
                                                const std::vector<double>& values);

}  // namespace stride::identify
