// The sensor packet byte for byte (nao-facts.md "LoLA"): 896 bytes, fixstr keys, float32 values,
// array16 for 25 elements; read back by an independent decoder (python3-msgpack) key by key, and
// a packet built by hand from the layout decodes into the expected SensorFrame.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "robot/hal/lola/sensor_packet.hpp"
#include "simulator/lola/lola_frames.hpp"
#include "tests/error_text.hpp"
#include "tests/lola/msgpack_bytes.hpp"
#include "tests/lola/python_decoder.hpp"

namespace stride {
namespace {

namespace lola = hal::lola;

// A frame with a different value in every slot, as a simulated NAO would send it.
hal::SensorFrame distinct_frame() {
  hal::SensorFrame s;
  for (int i = 0; i < hal::kNumJoints; ++i) {
    s.position[i] = 0.01 * i - 0.1234567;
    s.stiffness[i] = i / 25.0;
    s.current[i] = 0.05 * i;
    s.temperature[i] = 30 + 0.5 * i;
    s.status[i] = i % 4;
  }
  s.accelerometer = {0.31, -0.22, 9.79};
  s.gyroscope = {-0.314, 0.0123, 1e-3};
  s.angles = {0.02, -0.05};
  for (int i = 0; i < hal::kNumFsr; ++i) s.fsr[i] = 2.5 * i + 0.1;
  s.battery = {0.87, 2, -1.2, 41};
  s.sonar = {0.45, 2.5};
  for (int i = 0; i < hal::kNumTouch; ++i) s.touch[i] = i % 2;
  return s;
}

std::string packet_of(const hal::SensorFrame& s) {
  std::string out;
  sim::simulated_sensor_packet(s, out);
  return out;
}

// Element `index` of `key` as LoLA carries it (its sign and unit), rounded to float32.
double raw(const hal::SensorFrame& s, const std::string& key, int i) {
  auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  if (key == "Stiffness") return f(s.stiffness[i]);
  if (key == "Position") return f(s.position[i]);
  if (key == "Temperature") return f(s.temperature[i]);
  if (key == "Current") return f(s.current[i]);
  if (key == "Battery") return f(s.battery[i]);
  if (key == "Accelerometer") return f(i == 2 ? -s.accelerometer[i] : s.accelerometer[i]);
  if (key == "Gyroscope") return f(s.gyroscope[i]);
  if (key == "Angles") return f(s.angles[i]);
  if (key == "Sonar") return f(s.sonar[i]);
  if (key == "FSR") return f(s.fsr[i] / lola::kFsrNewtonPerKg);
  if (key == "Status") return s.status[i];
  if (key == "Touch") return f(s.touch[i]);
  ADD_FAILURE() << "no key " << key;
  return 0;
}

TEST(SensorPacket, SimulatorPacketIs896BytesWithLolaEncoding) {
  const std::string p = packet_of(distinct_frame());
  ASSERT_EQ(p.size(), 896u);
  EXPECT_EQ(static_cast<unsigned char>(p[0]), 0x8d);  // fixmap of 13 keys
  EXPECT_EQ(p.substr(1, 10), "\xa9Stiffness");          // fixstr key
  EXPECT_EQ(p.substr(11, 3), std::string("\xdc\x00\x19", 3));  // array16 of 25
  EXPECT_EQ(static_cast<unsigned char>(p[14]), 0xca);         // float32
  // Every key of the map is a fixstr and every float a float32: no float64 (0xcb) anywhere a
  // value starts, checked by walking the layout key by key.
  std::size_t at = 1;
  for (const auto& [key, length] : lola::kSensorKeys) {
    ASSERT_EQ(static_cast<unsigned char>(p[at]), 0xa0 + key.size()) << key;
    ASSERT_EQ(p.substr(at + 1, key.size()), key);
    at += 1 + key.size();
    if (length >= 16) {
      ASSERT_EQ(static_cast<unsigned char>(p[at]), 0xdc) << key;
      ASSERT_EQ(static_cast<unsigned char>(p[at + 2]), length) << key;
      at += 3;
    } else {
      ASSERT_EQ(static_cast<unsigned char>(p[at]), 0x90 + length) << key;
      at += 1;
    }
    for (int i = 0; i < length; ++i) {
      const auto tag = static_cast<unsigned char>(p[at]);
      if (key == "Status") {
        ASSERT_LT(tag, 0x80) << key << i;  // positive fixint
        at += 1;
      } else if (key == "RobotConfig") {
        ASSERT_EQ(tag & 0xe0, 0xa0) << key << i;  // fixstr
        at += 1 + (tag & 0x1f);
      } else {
        ASSERT_EQ(tag, 0xca) << key << i;
        at += 5;
      }
    }
  }
  EXPECT_EQ(at, p.size());
}

TEST(SensorPacket, IndependentDecoderReadsEveryKey) {
  const hal::SensorFrame s = distinct_frame();
  const test::PythonDecoded d = test::decode_with_python(packet_of(s));
  EXPECT_EQ(d.size, 896u);
  std::string expected_keys;
  for (const auto& k : lola::kSensorKeys)
    expected_keys += (expected_keys.empty() ? "" : ",") + std::string(k.key);
  EXPECT_EQ(d.keys, expected_keys);
  std::map<std::string, int> count;
  for (const auto& e : d.elements) {
    ++count[e.key];
    if (e.key == "RobotConfig") {
      EXPECT_EQ(e.type, "str");
      EXPECT_EQ(e.value, lola::kSimulatedRobotConfig[e.index]);
    } else {
      EXPECT_EQ(e.type, e.key == "Status" ? "int" : "float") << e.key << e.index;
      EXPECT_EQ(std::strtod(e.value.c_str(), nullptr), raw(s, e.key, e.index))
          << e.key << "[" << e.index << "]";
    }
  }
  for (const auto& [k, length] : lola::kSensorKeys) EXPECT_EQ(count[std::string(k)], length) << k;
}

TEST(SensorPacket, HandBuiltPacketDecodesToTheExpectedFrame) {
  test::MsgpackBytes m;
  m.fixmap(13);
  const auto floats = [&](std::string_view key, int n, auto value) {
    m.fixstr(key);
    m.array(n);
    for (int i = 0; i < n; ++i) m.float32(value(i));
  };
  floats("Stiffness", 25, [](int i) { return i == 7 ? 1.0f : 0.5f; });
  floats("Position", 25, [](int i) { return 0.25f * static_cast<float>(i) - 3.0f; });
  floats("Temperature", 25, [](int i) { return 40.0f + static_cast<float>(i); });
  floats("Current", 25, [](int i) { return 0.125f * static_cast<float>(i); });
  floats("Battery", 4, [](int i) { return std::array{0.75f, 3.0f, -1.5f, 35.0f}[i]; });
  floats("Accelerometer", 3, [](int i) { return std::array{0.5f, -0.25f, -9.75f}[i]; });
  floats("Gyroscope", 3, [](int i) { return std::array{0.125f, -0.5f, 2.0f}[i]; });
  floats("Angles", 2, [](int i) { return std::array{0.0625f, -0.125f}[i]; });
  floats("Sonar", 2, [](int i) { return std::array{0.5f, 5.0f}[i]; });
  floats("FSR", 8, [](int i) { return 0.5f * static_cast<float>(i); });  // kg
  m.fixstr("Status");
  m.array16(25);
  for (int i = 0; i < 25; ++i) m.fixint(i == 10 ? 3 : 0);
  floats("Touch", 14, [](int i) { return i == 0 ? 1.0f : 0.0f; });
  m.fixstr("RobotConfig");
  m.fixarray(4);
  for (auto s : lola::kSimulatedRobotConfig) m.fixstr(s);
  ASSERT_EQ(m.b.size(), 896u);  // the layout of nao-facts.md adds up to LoLA's size

  hal::SensorFrame f;
  f.time = 1.5;
  lola::decode_sensor_packet(m.b, f);
  EXPECT_EQ(f.time, 1.5);  // LoLA sends no clock
  EXPECT_EQ(f.stiffness[7], 1.0);
  EXPECT_EQ(f.stiffness[8], 0.5);
  EXPECT_EQ(f.position[hal::index(hal::JointId::HeadYaw)], -3.0);
  EXPECT_EQ(f.position[hal::index(hal::JointId::LKneePitch)], 0.25 * 10 - 3);
  EXPECT_EQ(f.position[hal::index(hal::JointId::RHand)], 0.25 * 24 - 3);
  EXPECT_EQ(f.temperature[3], 43.0);
  EXPECT_EQ(f.current[8], 1.0);
  EXPECT_EQ(f.battery, (std::array<double, 4>{0.75, 3, -1.5, 35}));
  // LoLA's z reads -9.75: the torso frame's +z up gives +9.75 standing.
  EXPECT_EQ(f.accelerometer, (std::array<double, 3>{0.5, -0.25, 9.75}));
  EXPECT_EQ(f.gyroscope, (std::array<double, 3>{0.125, -0.5, 2.0}));
  EXPECT_EQ(f.angles, (std::array<double, 2>{0.0625, -0.125}));
  EXPECT_EQ(f.sonar, (std::array<double, 2>{0.5, 5.0}));
  for (int i = 0; i < 8; ++i)  // kg on the wire, N in the frame, in LoLA's order
    EXPECT_DOUBLE_EQ(f.fsr[i], 0.5 * i * 9.80665) << hal::kFsrNames[i];
  EXPECT_EQ(f.status[10], 3);
  EXPECT_EQ(f.status[9], 0);
  EXPECT_EQ(f.touch[0], 1.0);
  EXPECT_EQ(f.touch[1], 0.0);
  EXPECT_EQ(f.robot_config[0], "P0000SIMULATEDBODY01");
  EXPECT_EQ(f.robot_config[3], "6.0.0");

  // And our encoder writes the very same bytes for that frame.
  std::string again;
  lola::encode_sensor_packet(f, again);
  EXPECT_EQ(again, m.b);
}

TEST(SensorPacket, RoundTripRoundsToFloat32Only) {
  const hal::SensorFrame s = distinct_frame();
  hal::SensorFrame d;
  lola::decode_sensor_packet(packet_of(s), d);
  for (int i = 0; i < hal::kNumJoints; ++i) {
    EXPECT_EQ(d.position[i], static_cast<float>(s.position[i]));
    EXPECT_EQ(d.status[i], s.status[i]);
  }
  EXPECT_EQ(d.accelerometer[2], static_cast<float>(s.accelerometer[2]));
  EXPECT_NEAR(d.fsr[5], s.fsr[5], 1e-6 * s.fsr[5]);
}

// One bad packet each: the error names the key and what was expected; the frame is untouched.
void expect_rejected(const std::string& packet, const std::string& message) {
  hal::SensorFrame f = distinct_frame();
  const hal::SensorFrame before = f;
  EXPECT_EQ(test_support::error_of([&] { lola::decode_sensor_packet(packet, f); }), message);
  EXPECT_EQ(f.position, before.position);
  EXPECT_EQ(f.robot_config, before.robot_config);
}

std::string replace_float(std::string p, std::string_view key, int index, float v) {
  const auto at = p.find(std::string(key)) + key.size() + 3 + 5 * index;
  test::MsgpackBytes m;
  m.float32(v);
  return p.replace(at, 5, m.b);
}

// A sensor packet in LoLA's layout with every value zero, written byte by byte; `skip` leaves a
// key out, `element` may write an element its own way (returns false to take the default), and
// the robot config strings set the size.
std::string layout_packet(std::string_view skip,
                          const std::function<bool(test::MsgpackBytes&, std::string_view, int)>& element,
                          const std::array<std::string, 4>& config) {
  test::MsgpackBytes m;
  m.fixmap(skip.empty() ? 13 : 12);
  for (const auto& [key, length] : lola::kSensorKeys) {
    if (key == skip) continue;
    m.fixstr(key);
    m.array(static_cast<unsigned>(length));
    for (int i = 0; i < length; ++i) {
      if (element && element(m, key, i)) continue;
      if (key == "Status")
        m.fixint(0);
      else if (key == "RobotConfig")
        m.fixstr(config[i]);
      else
        m.float32(0);
    }
  }
  return m.b;
}

const std::array<std::string, 4> kConfig = {std::string(lola::kSimulatedRobotConfig[0]), "6.0.0",
                                            std::string(lola::kSimulatedRobotConfig[2]), "6.0.0"};

TEST(SensorPacket, BadPacketsAreRejectedNamingWhatWasExpected) {
  const std::string good = packet_of(distinct_frame());
  expect_rejected(good.substr(0, 895), "LoLA sensor packet: 895 bytes (expected 896)");
  expect_rejected(good + "x", "LoLA sensor packet: 897 bytes (expected 896)");
  expect_rejected(replace_float(good, "Position", 10, std::nanf("")),
                  "LoLA sensor packet: Position: [10]: expected a finite number, got nan");
  expect_rejected(replace_float(good, "Current", 0, INFINITY),
                  "LoLA sensor packet: Current: [0]: expected a finite number, got inf");
  std::string renamed = good;  // same length: the size stays right
  renamed.replace(renamed.find("Gyroscope"), 9, "Gyroscopf");
  expect_rejected(renamed, "LoLA sensor packet: Gyroscopf: unknown key");
  std::string string_value = good;
  string_value.replace(string_value.find("Angles") + 7, 5, std::string("\xa4zero", 5));
  expect_rejected(string_value, "LoLA sensor packet: Angles: [0]: expected a number, got a string");
  std::string not_map = good;
  not_map[0] = static_cast<char>(0x9d);  // fixarray of 13 instead of fixmap
  hal::SensorFrame f;
  const std::string error = test_support::error_of([&] { lola::decode_sensor_packet(not_map, f); });
  EXPECT_TRUE(error.starts_with("LoLA sensor packet: ")) << error;
}

TEST(SensorPacket, WrongTypeMissingAndRepeatedKeysAreRejected) {
  ASSERT_EQ(layout_packet("", {}, kConfig).size(), 896u);
  // Status[3] as a float32 (4 bytes more), the body id 4 characters shorter: 896 bytes.
  auto config = kConfig;
  config[0].resize(config[0].size() - 4);
  const std::string float_status = layout_packet(
      "",
      [](test::MsgpackBytes& m, std::string_view key, int i) {
        if (key != "Status" || i != 3) return false;
        m.float32(1);
        return true;
      },
      config);
  ASSERT_EQ(float_status.size(), 896u);
  expect_rejected(float_status,
                  "LoLA sensor packet: Status: [3]: expected a 32-bit integer, got a float");
  // Sonar left out (17 bytes), the ids 17 characters longer: 896 bytes, one key missing.
  config = kConfig;
  config[0] += std::string(11, 'x');  // 31 characters: still a fixstr
  config[2] += std::string(6, 'x');
  const std::string no_sonar = layout_packet("Sonar", {}, config);
  ASSERT_EQ(no_sonar.size(), 896u);
  expect_rejected(no_sonar, "LoLA sensor packet: Sonar: missing key");
  // Touch's key renamed Sonar (same length): Sonar comes twice, the second with 14 elements.
  std::string twice = packet_of(distinct_frame());
  twice.replace(twice.find("Touch"), 5, "Sonar");
  expect_rejected(twice, "LoLA sensor packet: Sonar: key repeated");
}

}  // namespace
}  // namespace stride
