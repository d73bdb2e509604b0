// `stride sweep --through-lola`: every run's controller is a started `stride-robot` on a LoLA
// socket in lockstep. Its rows equal those of the same sweep in process through LoLA's packets
// (`--lola-packets`), with one worker or two; against the plain in-process sweep they differ by
// LoLA's 12 ms control period (10 ms in the scene). A robot process that cannot run makes its
// run a failed row saying why, and no process stays behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "robot/app/robot_config.hpp"
#include "robot/app/robot_config_text.hpp"
#include "tests/lola/lola_test_support.hpp"

namespace stride {
namespace {

using test::ChildProcess;
namespace fs = std::filesystem;

// Two short walks of the Ch. 4 hip scene (0.6 s of walking), the hip gain a factor: the run's
// setting must reach the robot process. The state hash says whether two worlds are the same. The
// trace traces no run: its controller key (unreadable through LoLA) must not fail the runs.
std::string tiny_sweep() {
  const std::string path = ChildProcess::scratch("lola_tiny.sweep.xml");
  std::ofstream(path)
      << "<sweep name=\"lola-tiny\">\n"
      << "  <scene file=\"" << test::kHipScene << "\"/>\n"
      << "  <factor name=\"kp\" target=\"HipStrategy.kp_pitch\" values=\"0.3 0.6\"/>\n"
      << "  <seeds count=\"1\" heading_spread=\"0.003\" position_spread=\"2mm\"/>\n"
      << "  <run until=\"walk_start+0.6s\"/>\n"
      << "  <record>\n"
      << "    <value name=\"hash\" key=\"sim.hash\"/>\n"
      << "    <value name=\"period\" key=\"robot.period\"/>\n"
      << "    <value name=\"fell\" key=\"walk.fell\"/>\n"
      << "    <summary name=\"pitch\" key=\"frame.true_pitch\" stat=\"max\" "
         "from=\"walk_start\"/>\n"
      << "    <trace where=\"kp == 9\" from=\"walk_start\">\n"
      << "      <column name=\"fsr\" key=\"representation:FsrSensorData.total_left\"/>\n"
      << "    </trace>\n"
      << "  </record>\n"
      << "</sweep>\n";
  return path;
}

struct SweepOut {
  int code = -1;
  std::string csv, err;
};

// The sweep with its own empty TMPDIR (where the robot processes' folders go), which must be
// empty again when it ends.
SweepOut sweep(const std::string& stride, const std::string& name, const std::string& link,
               int jobs) {
  const std::string out = ChildProcess::scratch(name);
  const std::string tmp = ChildProcess::scratch(name + "_tmp");
  fs::remove_all(out);
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  std::vector<std::string> args{
      "/usr/bin/env",       "TMPDIR=" + tmp, stride, "sweep",   tiny_sweep(), "--jobs",
      std::to_string(jobs), "--out",         out,    "--quiet", "--no-plots"};
  if (!link.empty()) args.push_back(link);
  ChildProcess p(args, name);
  SweepOut r;
  r.code = p.wait_for(300).value_or(-1);
  r.csv = test::read_file(out + "/runs.csv");
  r.err = p.err();
  EXPECT_TRUE(fs::is_empty(tmp)) << name << ": a robot process's folder stayed behind";
  fs::remove_all(tmp);
  return r;
}

TEST(LolaSweep, RowsThroughTheRobotProcessEqualTheInProcessRowsThroughTheSamePackets) {
  const SweepOut lola = sweep(test::kStride, "through_lola", "--through-lola", 1);
  ASSERT_EQ(lola.code, 0) << lola.err;
  const SweepOut packets = sweep(test::kStride, "lola_packets", "--lola-packets", 1);
  ASSERT_EQ(packets.code, 0) << packets.err;
  EXPECT_EQ(lola.csv, packets.csv) << "a robot process changed a run";
  EXPECT_NE(lola.csv.find(",ok,"), std::string::npos) << lola.csv;
  EXPECT_NE(lola.csv.find(",0.012,"), std::string::npos) << "LoLA's 12 ms period: " << lola.csv;
  const SweepOut workers = sweep(test::kStride, "through_lola_2", "--through-lola", 2);
  ASSERT_EQ(workers.code, 0) << workers.err;
  EXPECT_EQ(workers.csv, lola.csv) << "two workers changed a row";
  // In process at the scene's 10 ms: other frames, so another world (and its own hash).
  const SweepOut plain = sweep(test::kStride, "in_process", "", 1);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_NE(plain.csv.find(",0.01,"), std::string::npos) << plain.csv;
  EXPECT_NE(plain.csv, lola.csv);
}

TEST(LolaSweep, ARobotProcessThatEndsBeforeConnectingFailsItsRunInOneLine) {
  // A stride next to a `stride-robot` that says one line and exits 3.
  const fs::path dir = ChildProcess::scratch("fake_robot_dir");
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(test::kStride, dir / "stride");
  std::ofstream(dir / "stride-robot") << "#!/bin/sh\necho 'no robot here' >&2\nexit 3\n";
  fs::permissions(dir / "stride-robot", fs::perms::owner_all);
  const SweepOut r = sweep((dir / "stride").string(), "fake_robot", "--through-lola", 1);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.csv.find(",failed,"), std::string::npos) << r.csv;
  EXPECT_NE(r.csv.find("\"stride-robot (pid "), std::string::npos) << r.csv;
  EXPECT_EQ(r.csv.find("(pid -1"), std::string::npos) << r.csv;
  EXPECT_NE(r.csv.find("ended before it connected (exit status 3; its last line: no robot here)"),
            std::string::npos)
      << r.csv;
  EXPECT_NE(r.err.find("2 of 2 runs failed"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(LolaSweep, ARobotConfigWrittenBackReadsAsTheSameConfig) {
  RobotConfig c;
  c.urdf = STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf";
  c.lola_socket = "/tmp/x/lola";
  c.period = 0.012;
  c.link_timeout = 10;
  c.controller.providers["WalkingJointRequest"] = "PatternWalk";
  c.controller.parameters["PatternWalk.preset"] = "a \"quoted\" & <odd> value";
  c.controller.changes.push_back(
      {0.1, ControllerChange::Kind::Parameter, "HipStrategy.kp_pitch", "0.3"});
  c.controller.changes.push_back({0.1, ControllerChange::Kind::Provider, "JointRequest", "Stand"});
  c.controller.changes.push_back(
      {1.7, ControllerChange::Kind::Parameter, "HipStrategy.kp_pitch", "0.4"});
  const RobotConfig back = parse_robot_config_text(robot_config_xml(c), "written.xml");
  EXPECT_EQ(back.urdf, c.urdf);
  EXPECT_EQ(back.lola_socket, c.lola_socket);
  EXPECT_EQ(back.period, 0.012);
  EXPECT_EQ(back.link_timeout, 10.0);
  EXPECT_EQ(back.controller, c.controller);
}

}  // namespace
}  // namespace stride
