// <calibration sd=...>: seeded zero errors on the leg servos, a different robot for every seed.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "robot/core/error.hpp"
#include "robot/hal/joint_id.hpp"
#include "simulator/devices/calibration_spread.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

sim::DeviceDescription nao_devices() {
  return sim::load_device_file(test::source_path("scenes/robots/nao/nao.devices.xml"));
}

const sim::MimicJoints kNaoMimic = {{"RHipYawPitch", {"LHipYawPitch", 1.0}}};

std::vector<std::pair<std::string, double>> draw(sim::DeviceDescription& d, std::uint64_t seed,
                                                 double sd, std::vector<std::string> joints = {}) {
  sim::CalibrationSpread spread{sd, std::move(joints), "c.xml", 7};
  sim::NoiseSource noise(seed);
  return sim::draw_calibration_errors(d, spread, kNaoMimic, noise);
}

double offset_of(const sim::DeviceDescription& d, const std::string& joint) {
  for (const auto& s : d.servos)
    if (s.joint == joint) return s.offset;
  return NAN;
}

// By default every leg servo and nothing else; one motor turns both HipYawPitch joints, so they
// share one error; the error adds to an offset the scene already wrote.
TEST(CalibrationSpread, DrawsTheLegServosAndSharesTheHipYawPitchError) {
  sim::DeviceDescription d = nao_devices();
  for (auto& s : d.servos)
    if (s.joint == "LHipPitch") s.offset = 0.05;
  const auto errors = draw(d, 11, 0.5 * kDeg);
  ASSERT_EQ(errors.size(), 12u);
  for (const auto& [joint, error] : errors) {
    EXPECT_TRUE(sim::is_leg_joint(joint)) << joint;
    EXPECT_LT(std::abs(error), 5 * 0.5 * kDeg) << joint;
    EXPECT_NE(error, 0.0) << joint;
  }
  EXPECT_EQ(errors[0].first, "LHipYawPitch");
  EXPECT_EQ(errors[1].first, "RHipYawPitch");
  EXPECT_EQ(errors[0].second, errors[1].second);
  for (const auto& [joint, error] : errors) {
    if (joint == "LHipPitch") {
      EXPECT_DOUBLE_EQ(offset_of(d, joint), 0.05 + error);
    }
  }
  EXPECT_EQ(offset_of(d, "LShoulderPitch"), 0.0);
  EXPECT_EQ(offset_of(d, "HeadYaw"), 0.0);
}

TEST(CalibrationSpread, SameSeedSameErrorsOtherSeedOthers) {
  sim::DeviceDescription a = nao_devices(), b = nao_devices(), c = nao_devices();
  const auto ea = draw(a, 3, 1 * kDeg), eb = draw(b, 3, 1 * kDeg), ec = draw(c, 4, 1 * kDeg);
  EXPECT_EQ(ea, eb);
  for (size_t i = 0; i < ea.size(); ++i) EXPECT_NE(ea[i].second, ec[i].second) << ea[i].first;
}

// The errors are N(0, sd): over 2000 seeds x 11 independent joints the sample mean is within
// 4 standard errors of 0 and the sample standard deviation within 3 % of sd (its standard error
// is sd / sqrt(2 n) = 0.5 %).
TEST(CalibrationSpread, ErrorsHaveMeanZeroAndTheGivenSpread) {
  const double sd = 0.8 * kDeg;
  double sum = 0, sum2 = 0;
  int n = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    sim::DeviceDescription d = nao_devices();
    for (const auto& [joint, error] : draw(d, seed * 7919, sd)) {
      if (joint == "RHipYawPitch") continue;  // the left one's error again
      sum += error;
      sum2 += error * error;
      ++n;
    }
  }
  ASSERT_EQ(n, 2000 * 11);
  const double mean = sum / n, spread = std::sqrt(sum2 / n - mean * mean);
  EXPECT_LT(std::abs(mean), 4 * sd / std::sqrt(n));
  EXPECT_NEAR(spread, sd, 0.03 * sd);
}

// A named list draws only those; a mimic joint follows its leader even when not named.
TEST(CalibrationSpread, NamedJointsOnly) {
  sim::DeviceDescription d = nao_devices();
  const auto errors = draw(d, 5, 1 * kDeg, {"LKneePitch", "LHipYawPitch", "LShoulderRoll"});
  ASSERT_EQ(errors.size(), 4u);
  // In the device file's servo order.
  EXPECT_EQ(errors[0].first, "LShoulderRoll");
  EXPECT_EQ(errors[1].first, "LHipYawPitch");
  EXPECT_EQ(errors[2].first, "RHipYawPitch");
  EXPECT_EQ(errors[2].second, errors[1].second);
  EXPECT_EQ(errors[3].first, "LKneePitch");
  EXPECT_EQ(offset_of(d, "RKneePitch"), 0.0);
}

// A joint without a servo: one line naming where <calibration> was written; nothing drawn.
TEST(CalibrationSpread, UnknownJointChangesNothing) {
  sim::DeviceDescription d = nao_devices();
  try {
    draw(d, 5, 1 * kDeg, {"LKneePitch", "LKnee"});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("c.xml:7"), std::string::npos) << msg;
    EXPECT_NE(msg.find("no servo for 'LKnee'"), std::string::npos) << msg;
  }
  EXPECT_EQ(offset_of(d, "LKneePitch"), 0.0);
}

std::string hung_nao(int seed, const std::string& calibration) {
  return R"(<scene><ground enabled="false"/><physics solver="exact" seed=")" +
         std::to_string(seed) + R"("/>
    <robot name="nao" urdf="../../scenes/robots/nao/nao.urdf" devices="../../scenes/robots/nao/nao.devices.xml"
           xyz="0 0 1" fixed="true"><joints LHipPitch="-0.6"/><sensors noise="off"/>)" +
         calibration + "</robot></scene>";
}

// In the world: the hung leg's hip stands at its command plus the drawn error while its encoder
// reads the command; the report's errors are the ones in the joints; reset draws them again alike.
TEST(CalibrationSpread, TheDrawnErrorMovesTheJointNotItsEncoder) {
  auto sim = test::scene_from_text(hung_nao(9, R"(<calibration sd="2deg" joints="LHipPitch"/>)"));
  const auto errors = sim->robot(0).calibration_errors();
  ASSERT_EQ(errors.size(), 1u);
  const double error = errors[0].second;
  EXPECT_GT(std::abs(error), 0.05 * kDeg);
  sim->run_for(1.0);
  auto& robot = sim->robot(0);
  const int j = robot.model().joint_index("LHipPitch");
  EXPECT_NEAR(robot.body().joint_position(j), -0.6 + error, 1e-3);
  const double lsb = 2 * std::numbers::pi / 4096;
  EXPECT_NEAR(robot.latest_sensors().position[hal::index(hal::JointId::LHipPitch)], -0.6, lsb);
  const auto hash = sim->state_hash();
  sim->reset();
  EXPECT_EQ(sim->robot(0).calibration_errors(), errors);
  sim->run_for(1.0);
  EXPECT_EQ(sim->state_hash(), hash);
  auto other =
      test::scene_from_text(hung_nao(10, R"(<calibration sd="2deg" joints="LHipPitch"/>)"));
  EXPECT_NE(other->robot(0).calibration_errors()[0].second, error);
}

}  // namespace
}  // namespace stride
