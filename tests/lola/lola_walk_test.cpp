// `stride robot` walks the simulated NAO through the LoLA socket: two real processes, a real
// unix socket. In lockstep the state hash equals the in-process run through LoLA's packets
// (float32 exactly as the socket carries them): the process boundary changes nothing.
#include <gtest/gtest.h>

#include "tests/lola/lola_test_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;

struct LolaRun {
  std::string report, robot_out, robot_err, sim_err;
  int sim_code = -1, robot_code = -1;
};

// `stride run <scene> --seconds S --lola <socket> [extra]` with `stride robot` as its client.
LolaRun run_over_lola(const std::string& name, double seconds, const std::string& config,
                      const std::vector<std::string>& extra = {}) {
  const std::string socket = ChildProcess::scratch(name + ".sock");
  const std::string report = ChildProcess::scratch(name + ".json");
  std::vector<std::string> sim_args{test::kStride, "run", test::kHipScene, "--seconds",
                                    std::to_string(seconds), "--lola", socket, "--report", report};
  sim_args.insert(sim_args.end(), extra.begin(), extra.end());
  ChildProcess sim(sim_args, name + "_sim");
  EXPECT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config", config, "--lola", socket}, name + "_robot");
  LolaRun r;
  r.sim_code = sim.wait_for(300).value_or(-1);
  r.robot_code = robot.wait_for(30).value_or(-1);  // the link goes with the simulator
  r.report = test::read_file(report);
  r.robot_out = robot.out();
  r.robot_err = robot.err();
  r.sim_err = sim.err();
  return r;
}

TEST(LolaWalk, LockstepEqualsTheInProcessRunThroughLolaPacketsBitForBit) {
  const double seconds = 3.0;  // the CI walk: stand-up and the first steps
  const LolaRun lola = run_over_lola("lockstep", seconds, test::kHipConfig);
  ASSERT_EQ(lola.sim_code, 0) << lola.sim_err;
  const std::string in_process_report = ChildProcess::scratch("packets.json");
  ChildProcess packets({test::kStride, "run", test::kHipScene, "--seconds",
                        std::to_string(seconds), "--lola-packets", "--report", in_process_report},
                       "packets");
  ASSERT_EQ(packets.wait_for(300), 0) << packets.err();
  const std::string in_process = test::read_file(in_process_report);

  const std::string hash = test::json_value(lola.report, "state_hash");
  ASSERT_EQ(hash.size(), 16u) << lola.report;
  EXPECT_EQ(hash, test::json_value(in_process, "state_hash"))
      << "the LoLA run differs from the in-process run through the same packets";
  // Every one of the 250 frames of 12 ms went over the socket and was answered.
  EXPECT_EQ(test::json_value(lola.report, "pacing"), "lockstep");
  EXPECT_EQ(test::json_value(lola.report, "frames"), "250");
  EXPECT_EQ(test::json_value(lola.report, "exchanged"), "250");
  EXPECT_EQ(test::json_value(lola.report, "missed"), "0");
  EXPECT_EQ(test::json_value(lola.report, "fell"), "false");
  // The robot ran every frame, then saw the simulator go and gave up after its link timeout.
  EXPECT_EQ(lola.robot_code, 2) << lola.robot_err;
  EXPECT_NE(lola.robot_out.find("frames 250  LoLA packets 250 (bad 0"), std::string::npos)
      << lola.robot_out;
  EXPECT_NE(lola.robot_err.find("LoLA link lost (socket closed)"), std::string::npos)
      << lola.robot_err;
}

TEST(LolaWalk, RealtimePacesFramesByTheWallClockAndCountsMissedFrames) {
  const double seconds = 1.2;
  const auto begin = std::chrono::steady_clock::now();
  const LolaRun r = run_over_lola(
      "realtime", seconds, test::robot_config("realtime_stand", test::kStandController, ""),
      {"--realtime"});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  ASSERT_EQ(r.sim_code, 0) << r.sim_err;
  EXPECT_EQ(test::json_value(r.report, "pacing"), "realtime");
  EXPECT_EQ(test::json_value(r.report, "frames"), "100");
  const int exchanged = std::stoi(test::json_value(r.report, "exchanged"));
  const int missed = std::stoi(test::json_value(r.report, "missed"));
  EXPECT_EQ(exchanged + missed, 100);  // every frame is one or the other
  EXPECT_GE(exchanged, 50);            // a loaded CI machine may miss some; never most
  EXPECT_GE(std::stod(test::json_value(r.report, "wall_time")), seconds - 0.012);
  EXPECT_GE(wall, seconds);
}

}  // namespace
}  // namespace stride
