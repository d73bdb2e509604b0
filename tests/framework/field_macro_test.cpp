// STRIDE_FIELD names each field once: it declares the member (type and initialiser as written)
// and its entry of fields() (name, unit, range, element names), in declaration order.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <type_traits>

#include "robot/framework/binary.hpp"
#include "robot/framework/reflect.hpp"
#include "robot/framework/text.hpp"

namespace stride {
namespace {

inline constexpr std::array<std::string_view, 3> kAxes{"x", "y", "z"};

struct Declared {
  STRIDE_FIELDS(Declared);
  STRIDE_FIELD(double, knee, "rad", Range{-0.09, 2.11}) = 0.5;
  STRIDE_FIELD((std::array<double, 3>), gyro, "rad/s", {}, kAxes){1, 2, 3};
  std::string not_a_field = "kept out";  // a plain member stays out of the list
  STRIDE_FIELD(int, count) = 7;
  static constexpr std::string_view kTypeName = "Declared";
};

template <int N>
struct Templated {
  STRIDE_FIELDS(Templated);
  STRIDE_FIELD(double, value, "m") = N;
  static constexpr std::string_view kTypeName = "Templated";
};

static_assert(std::is_same_v<decltype(Declared::gyro), std::array<double, 3>>);
static_assert(
    std::is_same_v<decltype(Reflect<Declared>::fields()),
                   std::tuple<Field<Declared, double>, Field<Declared, std::array<double, 3>>,
                              Field<Declared, int>>>);

TEST(FieldMacro, EntriesFollowTheDeclarationsInOrder) {
  const auto [knee, gyro, count] = Reflect<Declared>::fields();
  EXPECT_EQ(knee.name, "knee");
  EXPECT_EQ(knee.member, &Declared::knee);
  EXPECT_EQ(knee.unit, "rad");
  ASSERT_TRUE(knee.range.has_value());
  EXPECT_EQ(knee.range->min, -0.09);
  EXPECT_EQ(knee.range->max, 2.11);
  EXPECT_EQ(gyro.name, "gyro");
  EXPECT_EQ(gyro.unit, "rad/s");
  EXPECT_FALSE(gyro.range.has_value());
  ASSERT_EQ(gyro.element_names.size(), 3u);
  EXPECT_EQ(gyro.element_names[2], "z");
  EXPECT_EQ(count.name, "count");
  EXPECT_EQ(count.unit, "");
}

TEST(FieldMacro, InitialisersAreTheMembersDefaults) {
  const Declared d;
  EXPECT_EQ(d.knee, 0.5);
  EXPECT_EQ(d.gyro, (std::array<double, 3>{1, 2, 3}));
  EXPECT_EQ(d.count, 7);
  EXPECT_EQ(d.not_a_field, "kept out");
  EXPECT_EQ(to_text(d), "{knee=0.5, gyro=[x=1, y=2, z=3], count=7}");
  EXPECT_EQ(Templated<4>{}.value, 4);
  EXPECT_EQ(to_text(Templated<4>{}), "{value=4}");
}

TEST(FieldMacro, BinaryRoundTripUsesTheFieldsOnly) {
  Declared d;
  d.knee = 1.25;
  d.gyro = {-1, 0.5, 9};
  d.count = -3;
  d.not_a_field = "local";
  const std::string bytes = to_binary(d);
  EXPECT_EQ(bytes.size(), sizeof(double) * 4 + sizeof(std::int32_t));
  Declared back;
  from_binary(back, bytes);
  EXPECT_EQ(back.knee, 1.25);
  EXPECT_EQ(back.gyro, d.gyro);
  EXPECT_EQ(back.count, -3);
  EXPECT_EQ(back.not_a_field, "kept out");
}

}  // namespace
}  // namespace stride
