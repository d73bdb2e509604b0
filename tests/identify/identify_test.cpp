// `stride identify` on simulated robots whose servos and gyro were changed by known amounts
// (issue 51's recovery test, the small version CI runs): the log of a held chirp recorded from
// the changed robot with the device file's noise; the fit recovers each changed gain within 10 %
// and the gyro bias within 0.1 deg/s; the identified model predicts a held-out motion (held
// steps) at least 3x closer than the nominal; the override file it writes, included in a scene,
// gives the robot those values.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>

#include "console/identify/identify.hpp"
#include "console/identify/identify_output.hpp"
#include "console/identify/residual.hpp"
#include "robot/runtime/log.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/identify/record_log.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;
using identify::IdentifyLog;

constexpr double kDeg = std::numbers::pi / 180;
const int kKnee = hal::index(hal::JointId::LKneePitch);
const int kHip = hal::index(hal::JointId::RHipPitch);

// The changed robot: knee gain +25 %, hip gain -25 %, gyro bias moved on every axis.
sim::ServoOverride gain_override(const char* joint, double gain) {
  sim::ServoOverride o;
  o.joint = joint;
  o.motor["gain"] = gain;
  o.file = "identify_test";
  return o;
}

const Eigen::Vector3d kBias(-15 * kDeg, -20 * kDeg, 1 * kDeg);

sim::SceneDescription changed(const std::string& motion, double seconds) {
  sim::SceneDescription s =
      sim::parse_scene_file(STRIDE_SOURCE_DIR "/scenes/identify/" + motion + ".xml");
  auto& r = s.robots[0];
  r.servos = {gain_override("LKneePitch", 250), gain_override("RHipPitch", 150)};
  r.gyro_bias = kBias;
  r.controller.parameters["Excitation.duration"] = std::to_string(seconds - 2.5);
  // A short log for CI: the sweep starts at 1 Hz instead of 0.3, where the joints move fast.
  r.controller.parameters["Excitation.f_low"] = "1";
  return s;
}

// Records `seconds` of the scene's robot as `stride run --log` does.
double rms_between(const std::vector<identify::LoggedFrame>& a,
                   const std::vector<identify::LoggedFrame>& b, int joint) {
  double sum = 0;
  for (std::size_t f = 0; f < a.size(); ++f)
    sum += std::pow(a[f].position[joint] - b[f].position[joint], 2);
  return std::sqrt(sum / static_cast<double>(a.size()));
}

TEST(Identify, RecoversChangedGainsAndGyroBiasAndPredictsAHeldOutMotion) {
  const auto robot = identify::robot_files("");
  const IdentifyLog log =
      identify::read_identify_log(test::record_log(changed("held_chirp", 8), 8, "id_chirp.log"));
  EXPECT_TRUE(log.held);
  identify::IdentifyRequest request;
  request.choice = identify::parse_param_list("gain,torque,gyro_bias");
  request.joints = {kKnee, kHip};
  request.iterations = 6;
  const auto result = identify::identify(log, robot, request);
  ASSERT_EQ(result.params.size(), 4u);
  for (const auto& p : result.params) {
    if (p.param.kind == identify::ParamKind::torque) {
      // Held in the air, no servo comes near its torque limit: said, not fitted.
      EXPECT_FALSE(p.identified) << p.param.name();
      EXPECT_EQ(p.value, p.param.nominal);
      continue;
    }
    const double truth = p.param.joint == kKnee ? 250 : 150;
    EXPECT_TRUE(p.identified) << p.param.name();
    EXPECT_NEAR(p.value, truth, 0.1 * truth) << p.param.name();
    std::cout << p.param.name() << " " << p.value << " +- " << p.half_width << "\n";
    EXPECT_LT(p.half_width, 0.1 * truth) << p.param.name();
  }
  ASSERT_TRUE(result.gyro);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(result.gyro->value[a], kBias[a], 0.1 * kDeg) << a;

  // The held-out motion: held steps of the same changed robot. Replayed noise-free with the true,
  // the identified and the nominal servos; the model's error is its distance from the truth.
  const IdentifyLog held_out =
      identify::read_identify_log(test::record_log(changed("held_steps", 8), 8, "id_steps.log"));
  std::vector<double> identified_gains, true_gains{250, 150}, nominal_gains{200, 200};
  for (const auto& p : result.params)
    if (p.param.kind == identify::ParamKind::gain) identified_gains.push_back(p.value);
  std::vector<identify::Param> gains;
  for (const auto& p : result.params)
    if (p.param.kind == identify::ParamKind::gain) gains.push_back(p.param);
  const auto truth =
      identify::replay(held_out, robot, identify::servo_overrides(gains, true_gains));
  const auto fitted =
      identify::replay(held_out, robot, identify::servo_overrides(gains, identified_gains));
  const auto nominal =
      identify::replay(held_out, robot, identify::servo_overrides(gains, nominal_gains));
  for (int j : {kKnee, kHip}) {
    SCOPED_TRACE(hal::kJointNames[j]);
    const double e_fit = rms_between(fitted, truth, j), e_nominal = rms_between(nominal, truth, j);
    EXPECT_GT(e_nominal, 1e-4) << j;  // the change is visible at all
    EXPECT_LE(3 * e_fit, e_nominal) << j;
  }

  // The override file, included in a scene's <robot>, gives the robot the fitted values.
  const std::string file = (fs::temp_directory_path() / "robot-id.xml").string();
  std::ofstream(file) << identify::override_text(result, "id_chirp.log");
  const std::string scene_file = (fs::temp_directory_path() / "id_scene.xml").string();
  std::ofstream(scene_file) << "<scene><robot urdf=\"" << robot.urdf << "\" devices=\""
                            << robot.devices
                            << "\"><include file=\"robot-id.xml\"/></robot></scene>";
  const auto scene = sim::parse_scene_file(scene_file);
  ASSERT_EQ(scene.robots[0].servos.size(), 2u);
  EXPECT_NEAR(scene.robots[0].servos[0].motor.at("gain"), identified_gains[0], 1e-3);
  EXPECT_NEAR(scene.robots[0].servos[1].motor.at("gain"), identified_gains[1], 1e-3);
  EXPECT_FALSE(scene.robots[0].servos[0].motor.contains("stall_torque"));  // not identified
  ASSERT_TRUE(scene.robots[0].gyro_bias);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR((*scene.robots[0].gyro_bias)[a], result.gyro->value[a], 1e-7);
}

}  // namespace
}  // namespace stride
