// The debug requests the shipped modules register, through the console on real scenes: each one
// shows the values its module computed (checked against the representations they end up in),
// and robot:stop_on_fall pauses a run when the robot falls.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"

namespace stride::console {
namespace {

const std::string kScenes = STRIDE_SOURCE_DIR "/scenes/";

class DebugRequestTest : public ::testing::Test {
 protected:
  std::string run(const std::string& line) {
    out.str("");
    console.execute(line);
    return out.str();
  }
  double number(const std::string& key) { return std::stod(target.get(key)); }

  LocalTarget target;
  std::ostringstream out;
  Interpreter console{target, out};
};

TEST_F(DebugRequestTest, PostureCorrectionsAndKalmanShowWhatTheModulesComputed) {
  run("load " + kScenes + "experiments/hip_medium.xml");
  const std::string list = run("dr ?");
  for (const char* name : {"posture:corrections off", "posture:kalman off", "walking:zmp off",
                           "balance:kalman off", "robot:stop_on_fall off"})
    EXPECT_NE(list.find(name), std::string::npos) << name << " in\n" << list;
  run("dr posture:corrections on");
  run("dr posture:kalman quiet");
  const std::string printed = run("run 0.1");
  EXPECT_NE(printed.find(" posture:corrections: pitch_correction="), std::string::npos);
  EXPECT_EQ(printed.find("posture:kalman:"), std::string::npos);  // quiet: values only
  // The printed values are the ones the strategy wrote into its representation this frame.
  EXPECT_DOUBLE_EQ(number("debug:posture:corrections.pitch_correction"),
                   number("representation:PostureCorrectedRequest.pitch_correction"));
  EXPECT_DOUBLE_EQ(number("debug:posture:corrections.roll_correction"),
                   number("representation:PostureCorrectedRequest.roll_correction"));
  EXPECT_DOUBLE_EQ(number("debug:posture:kalman.pitch"), number("representation:TorsoState.pitch"));
  EXPECT_DOUBLE_EQ(number("debug:posture:kalman.roll_rate"),
                   number("representation:TorsoState.roll_rate"));
  EXPECT_NE(number("debug:posture:corrections.pitch_correction"), 0.0);
}

TEST_F(DebugRequestTest, ZmpBesideTheCentreOfPressure) {
  run("load " + kScenes + "experiments/hip_medium.xml");
  run("dr walking:zmp quiet");
  run("run 0.2");
  const double dx = number("debug:walking:zmp.cop_x") - number("debug:walking:zmp.zmp_x");
  const double dy = number("debug:walking:zmp.cop_y") - number("debug:walking:zmp.zmp_y");
  EXPECT_NEAR(number("debug:walking:zmp.error"), std::hypot(dx, dy), 1e-9);
  // Standing before the walk: the planned ZMP is between the feet, the CoP under the soles.
  EXPECT_LT(number("debug:walking:zmp.error"), 0.05);
}

TEST_F(DebugRequestTest, BalanceKalmanAndStopOnFall) {
  run("load " + kScenes + "nao_stand_controlled.xml");
  run("mr JointRequest AnkleBalance");
  run("dr balance:kalman quiet");
  run("dr robot:stop_on_fall quiet");
  run("run 0.3");
  EXPECT_DOUBLE_EQ(number("debug:balance:kalman.com_x"), number("representation:ComState.x"));
  EXPECT_DOUBLE_EQ(number("debug:balance:kalman.zmp_y"), number("representation:ComState.zmp_y"));
  EXPECT_DOUBLE_EQ(number("debug:balance:kalman.measured_com_x"),
                   number("representation:ComState.measured_com[0]"));
  // A shove no ankle strategy can hold: the run pauses when the IMU passes fall_tilt.
  run("push torso 60 0 0 0.2");
  const std::string stopped = run("run 5");
  EXPECT_NE(stopped.find(": robot:stop_on_fall: fell: IMU tilt"), std::string::npos) << stopped;
  EXPECT_LT(number("sim.time"), 5.0);
  const double tilt = std::max(std::abs(number("representation:InertialSensorData.angles[0]")),
                               std::abs(number("representation:InertialSensorData.angles[1]")));
  EXPECT_GT(tilt, number("module:SensorConversion.fall_tilt"));
}

}  // namespace
}  // namespace stride::console
