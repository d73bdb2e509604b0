#include "robot/hal/lola/sensor_packet.hpp"

#include "robot/core/error.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "robot/hal/lola/msgpack_fields.hpp"
#include "robot/hal/lola/msgpack_sink.hpp"

namespace stride::hal::lola {
namespace {

constexpr std::string_view kWhat = "LoLA sensor packet";

template <std::size_t N>
void pack_floats(Packer& p, const std::array<double, N>& v, double scale = 1) {
  p.pack_array(N);
  for (double x : v) pack_float32(p, static_cast<float>(x * scale));
}

}  // namespace

std::array<double, 3> lola_accelerometer(const std::array<double, 3>& torso) {
  return {torso[0], torso[1], -torso[2]};  // LoLA's z reads about -9.81 standing
}

std::array<double, 3> torso_accelerometer(const std::array<double, 3>& lola) {
  return {lola[0], lola[1], -lola[2]};
}

void encode_sensor_packet(const SensorFrame& s, std::string& out) {
  encode_sensor_packet(
      s, {s.robot_config[0], s.robot_config[1], s.robot_config[2], s.robot_config[3]}, out);
}

void encode_sensor_packet(const SensorFrame& s, const std::array<std::string_view, 4>& robot_config,
                          std::string& out) {
  out.clear();
  StringSink sink{out};
  Packer p(sink);
  p.pack_map(static_cast<std::uint32_t>(kSensorKeys.size()));
  pack_key(p, "Stiffness");
  pack_floats(p, s.stiffness);
  pack_key(p, "Position");
  pack_floats(p, s.position);
  pack_key(p, "Temperature");
  pack_floats(p, s.temperature);
  pack_key(p, "Current");
  pack_floats(p, s.current);
  pack_key(p, "Battery");
  pack_floats(p, s.battery);
  pack_key(p, "Accelerometer");
  pack_floats(p, lola_accelerometer(s.accelerometer));
  pack_key(p, "Gyroscope");
  pack_floats(p, s.gyroscope);
  pack_key(p, "Angles");
  pack_floats(p, s.angles);
  pack_key(p, "Sonar");
  pack_floats(p, s.sonar);
  pack_key(p, "FSR");
  pack_floats(p, s.fsr, 1 / kFsrNewtonPerKg);
  pack_key(p, "Status");
  p.pack_array(kNumJoints);
  for (std::int32_t v : s.status) p.pack_int32(v);
  pack_key(p, "Touch");
  pack_floats(p, s.touch);
  pack_key(p, "RobotConfig");
  p.pack_array(4);
  for (std::string_view v : robot_config) pack_key(p, v);
}

void decode_sensor_packet(std::span<const char> packet, SensorFrame& out) {
  if (packet.size() != kSensorPacketSize)
    throw Error(std::string(kWhat) + ": " + std::to_string(packet.size()) + " bytes (expected " +
                std::to_string(kSensorPacketSize) + ")");
  const msgpack::object_handle h = unpack_packet(packet, kWhat);
  decode_sensor_map(h.get(), packet.size(), out);
}

void decode_sensor_map(const msgpack::object& map, std::size_t size, SensorFrame& out) {
  if (size != kSensorPacketSize)
    throw Error(std::string(kWhat) + ": " + std::to_string(size) + " bytes (expected " +
                std::to_string(kSensorPacketSize) + ")");
  const MapReader r(map, kWhat);
  SensorFrame f;
  f.time = out.time;
  std::array<bool, kSensorKeys.size()> seen{};
  std::array<double, 3> acc{};
  std::array<std::string_view, 4> config;  // assigned to `out` only once all is well
  for (std::size_t i = 0; i < r.size(); ++i) {
    const std::string_view key = r.key(i);
    std::size_t k = 0;
    while (k < kSensorKeys.size() && kSensorKeys[k].key != key) ++k;
    if (k == kSensorKeys.size()) r.fail(key, "unknown key");
    if (seen[k]) r.fail(key, "key repeated");
    seen[k] = true;
    switch (k) {
      case 0:
        r.numbers(i, f.stiffness);
        break;
      case 1:
        r.numbers(i, f.position);
        break;
      case 2:
        r.numbers(i, f.temperature);
        break;
      case 3:
        r.numbers(i, f.current);
        break;
      case 4:
        r.numbers(i, f.battery);
        break;
      case 5:
        r.numbers(i, acc);
        break;
      case 6:
        r.numbers(i, f.gyroscope);
        break;
      case 7:
        r.numbers(i, f.angles);
        break;
      case 8:
        r.numbers(i, f.sonar);
        break;
      case 9:
        r.numbers(i, f.fsr);
        break;
      case 10:
        r.integers(i, f.status);
        break;
      case 11:
        r.numbers(i, f.touch);
        break;
      default:
        r.strings(i, config);
        break;
    }
  }
  for (std::size_t k = 0; k < kSensorKeys.size(); ++k)
    if (!seen[k]) r.fail(kSensorKeys[k].key, "missing key");
  f.accelerometer = torso_accelerometer(acc);
  for (double& v : f.fsr) v *= kFsrNewtonPerKg;
  std::swap(f.robot_config, out.robot_config);  // keeps their buffers: no allocation
  out = std::move(f);
  for (int k = 0; k < 4; ++k) out.robot_config[k].assign(config[k]);
}

}  // namespace stride::hal::lola
