// Text, binary, CSV and type-description forms derived from field lists.
#include <gtest/gtest.h>

#include <random>

#include "behaviours/stand/stand.hpp"
#include "robot/framework/text.hpp"
#include "robot/representations/frame_info.hpp"
#include "robot/representations/fsr_sensor_data.hpp"
#include "robot/representations/hal_reflection.hpp"
#include "robot/representations/inertial_sensor_data.hpp"
#include "robot/representations/joint_request.hpp"
#include "robot/representations/joint_sensor_data.hpp"
#include "robot/runtime/nao_io_modules.hpp"
#include "tests/error_text.hpp"

namespace stride {

enum class Colour { Red, Green, Blue };
template <>
struct EnumNames<Colour> {
  static constexpr std::string_view type_name = "Colour";
  static constexpr std::array<std::string_view, 3> names{"Red", "Green", "Blue"};
};

namespace {

struct Inner {
  STRIDE_FIELDS(Inner);
  STRIDE_FIELD(double, a, "m", Range{-100, 100}) = 0;
  STRIDE_FIELD(Eigen::Vector2d, v) = Eigen::Vector2d::Zero();
  static constexpr std::string_view kTypeName = "Inner";
};

struct Everything {
  STRIDE_FIELDS(Everything);
  STRIDE_FIELD(bool, flag) = false;
  STRIDE_FIELD(std::int32_t, i) = 0;
  STRIDE_FIELD(std::int64_t, l) = 0;
  STRIDE_FIELD(std::uint8_t, u) = 0;
  STRIDE_FIELD(float, f) = 0;
  STRIDE_FIELD(double, d) = 0;
  STRIDE_FIELD(std::string, s);
  STRIDE_FIELD(Colour, colour) = Colour::Red;
  STRIDE_FIELD((std::array<Inner, 2>), inner){};
  STRIDE_FIELD(Eigen::Matrix3d, m) = Eigen::Matrix3d::Zero();
  STRIDE_FIELD(Eigen::Vector3f, vf) = Eigen::Vector3f::Zero();
  STRIDE_FIELD(std::vector<double>, list);
  STRIDE_FIELD((std::array<std::array<std::int32_t, 2>, 2>), grid){};
  static constexpr std::string_view kTypeName = "Everything";
};

// Fills every leaf with a pseudo-random value of its kind (full-precision doubles, all enums).
void randomise(const TypeDesc& d, Value& v, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> real(-10, 10);
  switch (d.kind) {
    case Kind::Bool:
      v.data = static_cast<bool>(rng() & 1);
      break;
    case Kind::Double:
      v.data = real(rng);
      break;
    case Kind::Float:
      v.data = double{static_cast<float>(real(rng))};
      break;
    case Kind::String:
      v.data = std::string("say \"hi\", x=[1]\\") + std::to_string(rng() % 100);
      break;
    case Kind::Enum:
      v.data = static_cast<std::int64_t>(rng() % d.enumerators.size());
      break;
    case Kind::UInt8:
      v.data = static_cast<std::int64_t>(rng() % 256);
      break;
    case Kind::Array:
    case Kind::Struct:
      for (std::size_t i = 0; auto& e : std::get<Value::List>(v.data))
        randomise(d.kind == Kind::Array ? *d.element : *d.fields[i++].type, e, rng);
      break;
    case Kind::List: {
      auto& items = std::get<Value::List>(v.data);
      items.assign(1 + rng() % 4, default_value(*d.element));
      for (auto& e : items) randomise(*d.element, e, rng);
      break;
    }
    default:
      v.data = static_cast<std::int64_t>(rng() % 2000) - 1000;
      break;
  }
}

// Keeps ranged leaves inside their range so the text form accepts them back.
void respect_ranges(const TypeDesc& d, Value& v, const std::optional<Range>& range) {
  if (d.kind == Kind::Struct) {
    auto& items = std::get<Value::List>(v.data);
    for (std::size_t k = 0; k < d.fields.size(); ++k)
      respect_ranges(*d.fields[k].type, items[k], d.fields[k].range ? d.fields[k].range : range);
  } else if (d.kind == Kind::Array || d.kind == Kind::List) {
    for (auto& e : std::get<Value::List>(v.data)) respect_ranges(*d.element, e, range);
  } else if (range && d.kind == Kind::Double) {
    v.data = range->min + 0.37 * (range->max - range->min);
  }
}

template <class T>
T random_value(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const auto& d = *describe<T>();
  Value v = default_value(d);
  randomise(d, v, rng);
  respect_ranges(d, v, std::nullopt);
  T out{};
  from_value(out, v);
  return out;
}

template <class T>
class RoundTrip : public ::testing::Test {};

using AllTypes =
    ::testing::Types<hal::SensorFrame, hal::ActuatorFrame, FrameInfo, ModuleTimes, JointSensorData,
                     InertialSensorData, FsrSensorData, JointRequest, behaviours::StandParameters,
                     SensorConversionParameters, Everything>;
TYPED_TEST_SUITE(RoundTrip, AllTypes);

TYPED_TEST(RoundTrip, BinaryReadsBackTheSameBits) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto v = random_value<TypeParam>(seed);
    const auto bytes = to_binary(v);
    TypeParam back{};
    from_binary(back, bytes);
    EXPECT_EQ(to_binary(back), bytes);
  }
}

TYPED_TEST(RoundTrip, TextReadsBackTheSameBits) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto v = random_value<TypeParam>(seed);
    const auto text = to_text(v);
    const auto back = from_text<TypeParam>(text);
    EXPECT_EQ(to_binary(back), to_binary(v)) << text;
  }
}

TYPED_TEST(RoundTrip, SerialisedDescriptionDecodesTheBinaryForm) {
  // What a console from another revision does: read the description, then the data.
  std::string desc_bytes;
  ByteWriter w(desc_bytes);
  write_type_desc(w, *describe<TypeParam>());
  ByteReader r(desc_bytes);
  const auto foreign = read_type_desc(r);
  EXPECT_TRUE(same_type(*foreign, *describe<TypeParam>()));
  const auto v = random_value<TypeParam>(7);
  const auto bytes = to_binary(v);
  ByteReader data(bytes);
  EXPECT_EQ(print_value(*foreign, read_value(*foreign, data)), to_text(v));
  EXPECT_EQ(data.remaining(), 0u);
}

TEST(Text, PrintsStructsArraysEnumsAndShortestDoubles) {
  FrameInfo f{0.1, 3, 0.012};
  EXPECT_EQ(to_text(f), "{time=0.1, frame=3, period=0.012}");
  Inner in{1.5, Eigen::Vector2d(-2, 0.25)};
  EXPECT_EQ(to_text(in), "{a=1.5, v=[-2, 0.25]}");
  Everything e;
  e.colour = Colour::Blue;
  e.s = "a \"b\"";
  const auto text = to_text(e);
  EXPECT_NE(text.find("colour=Blue"), std::string::npos);
  EXPECT_NE(text.find("s=\"a \\\"b\\\"\""), std::string::npos);
  EXPECT_NE(text.find("m=[[0, 0, 0], [0, 0, 0], [0, 0, 0]]"), std::string::npos);
}

TEST(Text, PartialUpdateChangesOnlyTheNamedFields) {
  FsrSensorData f;
  update_from_text(f, "force[3]=0.5 cop_left.x=0.01 cop_right[1]=-0.02 contact_left=true");
  EXPECT_EQ(f.force[3], 0.5);
  EXPECT_EQ(f.force[2], 0.0);
  EXPECT_EQ(f.cop_left.x(), 0.01);
  EXPECT_EQ(f.cop_right.y(), -0.02);
  EXPECT_TRUE(f.contact_left);
  Everything e;
  update_from_text(e, "inner[1].v.y=4 m[2][0]=7 colour=Green list=[1, 2, 3] grid[1]=[5, 6]");
  EXPECT_EQ(e.inner[1].v.y(), 4.0);
  EXPECT_EQ(e.m(2, 0), 7.0);
  EXPECT_EQ(e.colour, Colour::Green);
  EXPECT_EQ(e.list, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(e.grid[1][1], 6);
}

using stride::test_support::error_of;

TEST(Text, ErrorsNameTheFieldAndWhatWasExpected) {
  JointRequest r;
  auto update = [&](std::string_view t) { return error_of([&] { update_from_text(r, t); }); };
  EXPECT_EQ(update("position[3]=abc"), "JointRequest.position[3]: expected a number, got 'abc'");
  EXPECT_EQ(update("mode[0]=Fast"),
            "JointRequest.mode[0]: expected one of Position|Torque, got 'Fast'");
  EXPECT_EQ(update("stiffness[2]=1.5"), "JointRequest.stiffness[2]: 1.5 is outside [0, 1]");
  EXPECT_EQ(update("position[25]=0"), "JointRequest.position[25]: index out of range [0, 25)");
  EXPECT_EQ(update("speed=1"),
            "JointRequest: no field 'speed' (fields: mode, position, stiffness, torque)");
  EXPECT_EQ(update("position=[1, 2]"), "JointRequest.position: expected 25 elements, got 2");
  EXPECT_EQ(update("position[1]"), "JointRequest.position[1]: expected '=', got end of text");
  Everything e;
  EXPECT_EQ(error_of([&] { update_from_text(e, "u=300"); }),
            "Everything.u: expected an integer in [0, 255], got '300'");
  EXPECT_EQ(error_of([&] { update_from_text(e, "inner[0].a=200"); }),
            "Everything.inner[0].a: 200 is outside [-100, 100]");
  EXPECT_EQ(error_of([&] { update_from_text(e, "flag=maybe"); }),
            "Everything.flag: expected true or false, got 'maybe'");
}

TEST(Text, FailedUpdateChangesNothing) {
  JointRequest r;
  r.position[3] = 0.25;
  EXPECT_THROW(update_from_text(r, "position[3]=0.5 position[4]=oops"), Error);
  EXPECT_EQ(r.position[3], 0.25);
  EXPECT_EQ(r.position[4], 0.0);
}

TEST(Csv, ColumnsAreFlattenedPathsAndCellsMatch) {
  std::vector<std::string> cols, cells;
  csv_columns(*describe<Inner>(), "Inner", cols);
  EXPECT_EQ(cols, (std::vector<std::string>{"Inner.a", "Inner.v[0]", "Inner.v[1]"}));
  csv_cells(*describe<Inner>(), to_value(Inner{1.5, Eigen::Vector2d(2, 3)}), cells);
  EXPECT_EQ(cells, (std::vector<std::string>{"1.5", "2", "3"}));
}

TEST(TypeDescription, ListsFieldsTypesUnitsAndRanges) {
  const auto text = describe_text(*describe<behaviours::StandParameters>());
  EXPECT_NE(text.find("knee_pitch: double [rad] in [-0.0923279, 2.11255]"), std::string::npos)
      << text;
  const auto jr = describe_text(*describe<JointRequest>());
  EXPECT_NE(jr.find("mode: ServoMode[25] (Position|Torque)"), std::string::npos) << jr;
}

TEST(Binary, TruncatedDataIsAnErrorAndLeavesTheValue) {
  JointRequest r;
  r.position[0] = 1;
  auto bytes = to_binary(r);
  JointRequest other;
  EXPECT_THROW(from_binary(other, std::string_view(bytes).substr(0, bytes.size() - 1)), Error);
  EXPECT_EQ(other.position[0], 0.0);
}

TEST(Binary, HostileInputIsAnErrorNotACrash) {
  auto bytes = to_binary(ModuleTimes{{"a"}, {1}});
  bytes[3] = '\x7f';  // the first list now claims about two billion entries
  ModuleTimes m;
  EXPECT_EQ(error_of([&] { from_binary(m, bytes); }),
            "binary data: list length 2130706433 too large");
  ByteReader data(bytes);
  EXPECT_THROW(read_value(*describe<ModuleTimes>(), data), Error);
  const std::string bad_kind(1, static_cast<char>(99));
  ByteReader desc(bad_kind);
  EXPECT_EQ(error_of([&] { read_type_desc(desc); }), "type description: unknown kind 99");
}

}  // namespace
}  // namespace stride
