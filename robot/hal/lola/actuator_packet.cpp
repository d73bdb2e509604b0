#include "robot/hal/lola/actuator_packet.hpp"

#include "robot/core/error.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "robot/hal/lola/msgpack_fields.hpp"
#include "robot/hal/lola/msgpack_sink.hpp"

namespace stride::hal::lola {
namespace {

constexpr std::string_view kWhat = "LoLA actuator packet";

}  // namespace

void encode_actuator_packet(const ActuatorFrame& a, std::string& out) {
  for (int i = 0; i < kNumJoints; ++i)
    if (a.mode[i] != ServoMode::Position)
      throw Error("LoLA: joint " + std::string(kJointNames[i]) +
                  " commands torque mode; the physical NAO takes positions and stiffness only");
  out.clear();
  StringSink sink{out};
  Packer p(sink);
  p.pack_map(static_cast<std::uint32_t>(kActuatorKeys.size()));
  for (const auto& [key, length] : kActuatorKeys) {
    pack_key(p, key);
    p.pack_array(static_cast<std::uint32_t>(length));
    for (int i = 0; i < length; ++i) {
      if (key == "Position")
        pack_float32(p, static_cast<float>(a.position[i]));
      else if (key == "Stiffness")
        pack_float32(p, static_cast<float>(a.stiffness[i]));
      else if (key == "Sonar")
        p.pack_true();
      else
        pack_float32(p, 0.0f);  // LEDs off
    }
  }
}

ActuatorCommand decode_actuator_packet(std::span<const char> packet) {
  if (packet.size() > kMaxPacketSize)
    throw Error(std::string(kWhat) + ": " + std::to_string(packet.size()) + " bytes (at most " +
                std::to_string(kMaxPacketSize) + ")");
  const msgpack::object_handle h = unpack_packet(packet, kWhat);
  return decode_actuator_map(h.get());
}

ActuatorCommand decode_actuator_map(const msgpack::object& map) {
  const MapReader r(map, kWhat);
  ActuatorCommand c;
  std::array<bool, kActuatorKeys.size()> seen{};
  std::array<double, 24> leds{};
  std::array<bool, 2> sonar{};
  for (std::size_t i = 0; i < r.size(); ++i) {
    const std::string_view key = r.key(i);
    std::size_t k = 0;
    while (k < kActuatorKeys.size() && kActuatorKeys[k].key != key) ++k;
    if (k == kActuatorKeys.size()) r.fail(key, "unknown key");
    if (seen[k]) r.fail(key, "key repeated");
    seen[k] = true;
    if (key == "Position")
      r.numbers(i, c.position.emplace());
    else if (key == "Stiffness")
      r.numbers(i, c.stiffness.emplace());
    else if (key == "Sonar")
      r.booleans(i, sonar);
    else  // LEDs: checked, not simulated
      r.numbers(i, std::span<double>(leds.data(), kActuatorKeys[k].length));
  }
  return c;
}

void apply_actuator_command(const ActuatorCommand& c, ActuatorFrame& frame) {
  for (int i = 0; i < kNumJoints; ++i) {
    frame.mode[i] = ServoMode::Position;
    if (c.position) frame.position[i] = (*c.position)[i];
    if (c.stiffness) frame.stiffness[i] = (*c.stiffness)[i];
  }
}

}  // namespace stride::hal::lola
