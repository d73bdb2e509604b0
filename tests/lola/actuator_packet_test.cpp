// The actuator map (nao-facts.md "LoLA"): the full map of a command is 786 bytes; a subset of keys
// is accepted; torque mode is refused; bad answers name the key.
#include <gtest/gtest.h>

#include "robot/hal/lola/actuator_packet.hpp"
#include "robot/hal/lola/lola_protocol.hpp"
#include "simulator/lola/lola_frames.hpp"
#include "tests/error_text.hpp"
#include "tests/lola/msgpack_bytes.hpp"
#include "tests/lola/python_decoder.hpp"

namespace stride {
namespace {

namespace lola = hal::lola;

hal::ActuatorFrame command() {
  hal::ActuatorFrame a;
  for (int i = 0; i < hal::kNumJoints; ++i) {
    a.position[i] = 0.02 * i - 0.2;
    a.stiffness[i] = i % 2 ? 1.0 : 0.6;
  }
  return a;
}

TEST(ActuatorPacket, FullMapIs786BytesAndRoundsToFloat32) {
  std::string p;
  lola::encode_actuator_packet(command(), p);
  ASSERT_EQ(p.size(), 786u);
  EXPECT_EQ(static_cast<unsigned char>(p[0]), 0x8b);  // fixmap of 11 keys
  EXPECT_EQ(p.substr(1, 9), "\xa8Position");
  EXPECT_EQ(p.substr(10, 3), std::string("\xdc\x00\x19", 3));
  hal::ActuatorFrame back;
  back.mode.fill(hal::ServoMode::Torque);
  sim::apply_lola_answer(p, back);
  for (int i = 0; i < hal::kNumJoints; ++i) {
    EXPECT_EQ(back.mode[i], hal::ServoMode::Position);
    EXPECT_EQ(back.position[i], static_cast<float>(command().position[i]));
    EXPECT_EQ(back.stiffness[i], static_cast<float>(command().stiffness[i]));
  }
}

TEST(ActuatorPacket, IndependentDecoderReadsEveryKey) {
  std::string p;
  lola::encode_actuator_packet(command(), p);
  const test::PythonDecoded d = test::decode_with_python(p);
  EXPECT_EQ(d.size, 786u);
  EXPECT_EQ(d.keys, "Position,Stiffness,Chest,LEar,REar,LEye,REye,LFoot,RFoot,Skull,Sonar");
  int positions = 0, leds = 0;
  for (const auto& e : d.elements) {
    if (e.key == "Position") {
      ++positions;
      EXPECT_EQ(std::strtod(e.value.c_str(), nullptr),
                static_cast<float>(command().position[e.index]));
    } else if (e.key == "Sonar") {
      EXPECT_EQ(e.type, "bool");
      EXPECT_EQ(e.value, "True");
    } else if (e.key != "Stiffness") {
      ++leds;
      EXPECT_EQ(e.value, "0.0") << e.key;  // LEDs off
    }
  }
  EXPECT_EQ(positions, 25);
  EXPECT_EQ(leds, 3 + 10 + 10 + 24 + 24 + 3 + 3 + 12);
}

TEST(ActuatorPacket, TorqueModeIsRefusedNamingTheJoint) {
  hal::ActuatorFrame a = command();
  a.mode[hal::index(hal::JointId::RKneePitch)] = hal::ServoMode::Torque;
  std::string p = "untouched";
  EXPECT_EQ(test_support::error_of([&] { lola::encode_actuator_packet(a, p); }),
            "LoLA: joint RKneePitch commands torque mode; the physical NAO takes positions and "
            "stiffness only");
  EXPECT_EQ(p, "untouched");
}

TEST(ActuatorPacket, SubsetReplacesOnlyItsKeys) {
  test::MsgpackBytes m;  // {"Stiffness": [0.25 x 25]} written by hand
  m.fixmap(1);
  m.fixstr("Stiffness");
  m.array16(25);
  for (int i = 0; i < 25; ++i) m.float32(0.25f);
  hal::ActuatorFrame f = command();
  sim::apply_lola_answer(m.b, f);
  EXPECT_EQ(f.position, command().position);
  for (double s : f.stiffness) EXPECT_EQ(s, 0.25);
  hal::ActuatorFrame g = command();
  sim::apply_lola_answer(std::string("\x80", 1), g);  // {}: nothing changes
  EXPECT_EQ(g.position, command().position);
  EXPECT_EQ(g.stiffness, command().stiffness);
}

std::string answer_error(const std::string& packet) {
  hal::ActuatorFrame f = command();
  const std::string e = test_support::error_of([&] { sim::apply_lola_answer(packet, f); });
  EXPECT_EQ(f.position, command().position) << "a bad answer changed the command";
  return e;
}

TEST(ActuatorPacket, BadAnswersNameTheKeyAndChangeNothing) {
  test::MsgpackBytes nan;
  nan.fixmap(1);
  nan.fixstr("Position");
  nan.array16(25);
  for (int i = 0; i < 25; ++i) nan.float32(i == 4 ? std::nanf("") : 0.0f);
  EXPECT_EQ(answer_error(nan.b),
            "LoLA actuator packet: Position: [4]: expected a finite number, got nan");
  test::MsgpackBytes short_array;
  short_array.fixmap(1);
  short_array.fixstr("Position");
  short_array.fixarray(3);
  for (int i = 0; i < 3; ++i) short_array.float32(0);
  EXPECT_EQ(answer_error(short_array.b),
            "LoLA actuator packet: Position: expected 25 elements, got 3");
  test::MsgpackBytes unknown;
  unknown.fixmap(1);
  unknown.fixstr("Torque");
  unknown.fixarray(0);
  EXPECT_EQ(answer_error(unknown.b), "LoLA actuator packet: Torque: unknown key");
  test::MsgpackBytes sonar;
  sonar.fixmap(1);
  sonar.fixstr("Sonar");
  sonar.fixarray(2);
  sonar.float32(1);
  sonar.boolean(true);
  EXPECT_EQ(answer_error(sonar.b), "LoLA actuator packet: Sonar: [0]: expected a boolean, got a float");
  EXPECT_EQ(answer_error(std::string("\x93\x01\x02\x03", 4)),
            "LoLA actuator packet: expected a map, got an array");
  EXPECT_EQ(answer_error(std::string("\x81\xa8Position", 10)),
            "LoLA actuator packet: 10 bytes end inside a msgpack value");
}

}  // namespace
}  // namespace stride
