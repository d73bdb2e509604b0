// Joint arrays by name: printed as [HeadYaw=..., ...], paths and texts accept the joint names,
// the type description carries the names and still matches one without them.
#include <gtest/gtest.h>

#include "robot/framework/text.hpp"
#include "robot/representations/hal_reflection.hpp"
#include "robot/representations/joint_request.hpp"
#include "tests/error_text.hpp"

namespace stride {
namespace {

using test_support::error_of;

TEST(NamedElements, PathsAndTextsTakeJointNames) {
  JointRequest r;
  update_from_text(r, "position[LAnklePitch]=0.25 stiffness[RHand]=0.5 mode[HeadYaw]=Torque");
  EXPECT_EQ(r.position[hal::index(hal::JointId::LAnklePitch)], 0.25);
  EXPECT_EQ(r.stiffness[hal::index(hal::JointId::RHand)], 0.5);
  EXPECT_EQ(r.mode[0], hal::ServoMode::Torque);
  // A list of named elements sets those and keeps the others.
  update_from_text(r, "position=[RKneePitch=1, LKneePitch=-0.5]");
  EXPECT_EQ(r.position[hal::index(hal::JointId::RKneePitch)], 1.0);
  EXPECT_EQ(r.position[hal::index(hal::JointId::LKneePitch)], -0.5);
  EXPECT_EQ(r.position[hal::index(hal::JointId::LAnklePitch)], 0.25);
  // Indices still work, and the text names every element.
  update_from_text(r, "position[0]=0.125");
  const std::string text = to_text(r);
  EXPECT_NE(text.find("position=[HeadYaw=0.125, HeadPitch=0, LShoulderPitch=0"), std::string::npos)
      << text;
  EXPECT_NE(text.find("LAnklePitch=0.25"), std::string::npos);
  // The printed text reads back to the same value.
  JointRequest back;
  update_from_text(back, text.substr(1, text.size() - 2));
  EXPECT_EQ(to_binary(back), to_binary(r));
}

TEST(NamedElements, BadNamesAreOneLineErrors) {
  JointRequest r;
  const JointRequest before = r;
  auto update = [&](const std::string& t) { return error_of([&] { update_from_text(r, t); }); };
  EXPECT_EQ(update("position[LAnkle]=0"),
            "JointRequest.position: no element 'LAnkle' (get <key> ? lists the names)");
  EXPECT_EQ(update("position=[LAnkle=1]"),
            "JointRequest.position: expected an element name (get <key> ? lists them), got "
            "'LAnkle'");
  EXPECT_EQ(update("stiffness[LHipRoll]=2"),
            "JointRequest.stiffness[LHipRoll]: 2 is outside [0, 1]");
  EXPECT_EQ(to_binary(r), to_binary(before));  // all or nothing
}

TEST(NamedElements, TypeDescriptionsCarryTheNames) {
  const TypeDesc& d = *describe<hal::SensorFrame>();
  const TypeDesc& position = *d.fields[1].type;
  ASSERT_EQ(position.element_names.size(), 25u);
  EXPECT_EQ(position.element_names[11], "LAnklePitch");
  EXPECT_EQ(element_index(position, "RHand"), 24);
  EXPECT_TRUE(describe<hal::SensorFrame>()->fields[8].type->element_names.empty());  // fsr
  std::string bytes;
  ByteWriter w(bytes);
  write_type_desc(w, d);
  ByteReader r(bytes);
  const TypeDescPtr back = read_type_desc(r);
  EXPECT_EQ(back->fields[1].type->element_names, position.element_names);
  EXPECT_NE(describe_text(*back).find("(elements: HeadYaw HeadPitch"), std::string::npos);
  // A description written before names existed (flags byte 0) is the same type.
  TypeDesc unnamed = d;
  auto plain = std::make_shared<TypeDesc>(position);
  plain->element_names.clear();
  unnamed.fields[1].type = plain;
  EXPECT_TRUE(same_type(unnamed, d));
  std::vector<std::string> columns;
  csv_columns(d, "SensorFrame", columns);
  EXPECT_EQ(columns[1], "SensorFrame.position[HeadYaw]");
}

TEST(NamedElements, HostileDescriptionsFailCleanly) {
  std::string bytes;
  ByteWriter w(bytes);
  w.put(static_cast<std::uint8_t>(Kind::Array));
  w.put_string("array");
  w.put(static_cast<std::uint64_t>(3));
  w.put(static_cast<std::uint8_t>(6));  // unknown flag bit
  ByteReader r(bytes);
  EXPECT_EQ(error_of([&] { read_type_desc(r); }), "type description: unknown array flags 6");
  bytes.back() = 2;  // names promised, none there
  ByteReader r2(bytes);
  EXPECT_NE(error_of([&] { read_type_desc(r2); }), "");
}

}  // namespace
}  // namespace stride
