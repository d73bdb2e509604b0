// Faults on the LoLA link, each with the real processes and a real unix socket: the simulator
// closes the socket or stalls mid-walk, bad sensor packets, the robot process killed, a module
// that throws.
#include <gtest/gtest.h>

#include "console/cli/lola_run.hpp"
#include "robot/hal/lola/actuator_packet.hpp"
#include "robot/hal/lola/packet_stream.hpp"
#include "robot/hal/unix_socket.hpp"
#include "simulator/lola/lola_frames.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "tests/lola/lola_test_support.hpp"
#include "tests/lola/msgpack_bytes.hpp"

namespace stride {
namespace {

using test::ChildProcess;
using Clock = std::chrono::steady_clock;

// The hip walk's robot config with another <safety> line.
std::string hip_config(const std::string& name, const std::string& safety) {
  std::string text = test::read_file(test::kHipConfig);
  const auto at = text.find("<safety");
  text.replace(at, text.find("/>", at) + 2 - at, "<safety " + safety + "/>");
  text.replace(text.find("../nao.urdf"), 11, STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf");
  const std::string path = ChildProcess::scratch(name + ".xml");
  std::ofstream(path) << text;
  return path;
}

// The number before " ms ago" in the robot's last report of a silent link (a busy machine may
// have made it report slow frames before).
double silent_ms(const std::string& err) {
  const auto silent = err.rfind("LoLA link silent");
  if (silent == std::string::npos) return -1;
  const auto at = err.find(" ms ago", silent);
  return std::stod(err.substr(err.rfind("packet ", at) + 7));
}

TEST(LolaFaults, SimulatorClosesTheSocketMidWalk) {
  const std::string socket = ChildProcess::scratch("close.sock");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "2.5", "--lola", socket},
                   "close_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config", hip_config("close", "link_timeout=\"0.3s\""),
                      "--lola", socket},
                     "close_robot");
  ASSERT_EQ(sim.wait_for(120), 0) << sim.err();
  const auto sim_gone = Clock::now();
  const auto code = robot.wait_for(10);
  const double after = std::chrono::duration<double>(Clock::now() - sim_gone).count();
  ASSERT_EQ(code, 2) << robot.err();  // non-zero: the link is gone for good
  EXPECT_LT(after, 3.0);              // the simulator's exit may come well after its socket closed
  const std::string err = robot.err();
  // It waited out its timeout since the last packet, holding, then gave up within a few frames.
  const auto gave_up = err.find("no LoLA link for ");
  ASSERT_NE(gave_up, std::string::npos) << err;
  const double lost_ms = std::stod(err.substr(gave_up + 17));
  EXPECT_GT(lost_ms, 300.0) << err;
  EXPECT_LT(lost_ms, 300.0 + 100.0) << err;
  EXPECT_NE(err.find("LoLA link lost (socket closed)"), std::string::npos) << err;
  EXPECT_NE(err.find("holding the last command; exiting if it is not back within 0.3 s"),
            std::string::npos)
      << err;
  EXPECT_NE(robot.out().find("frames 208 "), std::string::npos) << robot.out();  // 2.5 s / 12 ms
}

TEST(LolaFaults, SimulatorStallsAndTheRobotReportsWithinAFrame) {
  const std::string socket = ChildProcess::scratch("stall.sock");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "60", "--lola", socket},
                   "stall_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config", hip_config("stall", "link_timeout=\"0.5s\""),
                      "--lola", socket},
                     "stall_robot");
  std::this_thread::sleep_for(std::chrono::milliseconds(800));
  ASSERT_FALSE(robot.wait_for(0)) << robot.err();
  sim.signal(SIGSTOP);  // the simulator stops answering; its socket stays open
  ASSERT_EQ(robot.wait_for(20), 2) << robot.err();
  const std::string err = robot.err();
  ASSERT_NE(err.find("LoLA link silent"), std::string::npos) << err;
  // Reported after two periods without a packet, within the frame after that (slack for a busy
  // machine scheduling the robot process late).
  const double ms = silent_ms(err);
  EXPECT_GE(ms, 24.0) << err;
  EXPECT_LE(ms, 36.0 + 40.0) << err;
  EXPECT_NE(err.find("no LoLA link for"), std::string::npos) << err;
  sim.signal(SIGKILL);
}

// The test is the LoLA server: good packets, and four bad ones among them.
TEST(LolaFaults, BadSensorPacketsAreHeldCountedAndAnswered) {
  const std::string socket = ChildProcess::scratch("bad.sock");
  hal::UnixListener listener(socket);
  ChildProcess robot({test::kStrideRobot, "--config",
                      test::robot_config("bad", test::kStandController, ""), "--lola", socket},
                     "bad_robot");
  auto client = listener.accept(Clock::now() + std::chrono::seconds(60));
  ASSERT_TRUE(client) << robot.err();

  hal::SensorFrame s;
  s.position[hal::index(hal::JointId::LKneePitch)] = 0.6;
  s.stiffness.fill(1);
  std::string good;
  sim::simulated_sensor_packet(s, good);
  std::string wrong_size = good;  // a longer body id: 900 bytes
  wrong_size.replace(wrong_size.find("\xb4P0000SIMULATEDBODY01"), 21,
                     "\xb8P0000SIMULATEDBODY01xxxx");
  std::string wrong_type = good;
  wrong_type.replace(wrong_type.find("Angles") + 7, 5, std::string("\xa4zero", 5));
  std::string missing = good;  // "Sonar" renamed to an unknown key of the same length
  missing.replace(missing.find("Sonar"), 5, "Sonix");
  std::string nan = good;
  nan.replace(nan.find("Position") + 8 + 3 + 5 * 10, 5, std::string("\xca\x7f\xc0\x00\x00", 5));

  hal::lola::PacketStream stream;
  std::string previous;
  int held = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const std::string* p = &good;
    if (frame == 20) p = &wrong_size;
    if (frame == 25) p = &wrong_type;
    if (frame == 30) p = &missing;
    if (frame == 35) p = &nan;
    ASSERT_TRUE(client->send_all(*p));
    std::span<const char> answer;
    std::string error;
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    while (stream.next(answer, error) != hal::lola::PacketStream::Result::Packet) {
      ASSERT_EQ(client->wait_readable(deadline), hal::UnixSocket::Wait::Readable)
          << "no answer to frame " << frame << ": " << robot.err();
      const long n = client->receive(stream.reserve(4096));
      ASSERT_GT(n, 0) << robot.err();
      stream.commit(static_cast<std::size_t>(n));
    }
    const std::string a(answer.begin(), answer.end());
    ASSERT_EQ(a.size(), 786u) << "frame " << frame;  // every frame answered with a full command
    if (p != &good) {
      EXPECT_EQ(a, previous) << "frame " << frame << " was not held";
      ++held;
    }
    previous = a;
  }
  EXPECT_EQ(held, 4);
  robot.signal(SIGTERM);
  ASSERT_EQ(robot.wait_for(10), 0) << robot.err();  // stopped cleanly, no crash
  const std::string out = robot.out(), err = robot.err();
  EXPECT_NE(out.find("frames 56  LoLA packets 60 (bad 4, stale skipped 0)"), std::string::npos)
      << out;
  EXPECT_NE(out.find("first link error: LoLA sensor packet: 900 bytes (expected 896)"),
            std::string::npos)
      << out;
  EXPECT_NE(err.find("frame 20: LoLA sensor packet: 900 bytes (expected 896) (frame held)"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("SIGTERM: stopped after a complete frame"), std::string::npos) << err;
}

// The simulator in this process (the real LolaServer), the robot a real process, killed.
TEST(LolaFaults, RobotKilledMidWalkTheSimulatorReportsAndHolds) {
  const std::string socket = ChildProcess::scratch("kill.sock");
  cli::LolaRunOptions o;
  o.socket = socket;
  console::SimSession session(cli::lola_scene(sim::parse_scene_file(test::kHipScene), o));
  auto& sim = session.simulation();
  std::ostringstream events;
  sim::LolaServer server(socket, sim::LolaPacing::Lockstep, sim.robot(0), events);
  ChildProcess robot({test::kStrideRobot, "--config", test::kHipConfig, "--lola", socket},
                     "kill_robot");
  server.wait_for_client(60);
  sim.set_controller(0, &server);
  const hal::ActuatorFrame initial = sim.robot(0).latest_commands();
  sim.run_for(2.5);  // standing up, then walking
  robot.signal(SIGKILL);
  ASSERT_EQ(robot.wait_for(10), 128 + SIGKILL);
  for (int i = 0; i < 100 && server.report().clients_lost == 0; ++i) sim.run_for(0.012);
  ASSERT_EQ(server.report().clients_lost, 1) << events.str();
  EXPECT_NE(events.str().find("client lost (it closed the socket); robot 'nao' holds its last "
                              "command"),
            std::string::npos)
      << events.str();
  const hal::ActuatorFrame held = sim.robot(0).latest_commands();
  EXPECT_NE(held.position, initial.position);  // the robot had been commanding it
  sim.run_for(1.0);
  EXPECT_EQ(sim.robot(0).latest_commands().position, held.position);
  EXPECT_EQ(sim.robot(0).latest_commands().stiffness, held.stiffness);
  EXPECT_GT(server.report().without_client, 80);
}

TEST(LolaFaults, ModuleThatThrowsIsReportedOnceAndTheFrameHeld) {
  // At 1 s a parameter the walk cannot build: PatternWalk throws in every frame after it.
  std::string text = test::read_file(test::kHipConfig);
  text.replace(text.find("../nao.urdf"), 11, STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf");
  text.replace(text.find("</controller>"), 13,
               "<at time=\"1s\"><parameter module=\"PatternWalk\" field=\"z_max\" "
               "value=\"0.5\"/></at></controller>");
  const std::string config = ChildProcess::scratch("throws.xml");
  std::ofstream(config) << text;
  const std::string socket = ChildProcess::scratch("throws.sock");
  const std::string report = ChildProcess::scratch("throws.json");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "2", "--lola", socket,
                    "--report", report},
                   "throws_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config", config, "--lola", socket}, "throws_robot");
  ASSERT_EQ(sim.wait_for(120), 0) << sim.err();
  ASSERT_EQ(robot.wait_for(10), 2) << robot.err();
  const std::string err = robot.err(), out = robot.out(), json = test::read_file(report);
  const std::string line = "module 'PatternWalk' failed: WalkParameters: z_max = 0.5 m is beyond";
  const auto first = err.find(line);
  ASSERT_NE(first, std::string::npos) << err;
  EXPECT_EQ(err.find(line, first + 1), std::string::npos) << "reported more than once: " << err;
  EXPECT_NE(err.find("(holding the last safe command; going on)"), std::string::npos) << err;
  // 2 s of 12 ms frames: 166 (0 to 165); from frame 84 at 1.008 s on, 82 frames held, every one
  // still answered.
  EXPECT_NE(out.find("module 'PatternWalk' failed in 82 frames, first at frame 84"),
            std::string::npos)
      << out;
  EXPECT_EQ(test::json_value(json, "exchanged"), test::json_value(json, "frames"));
}

TEST(LolaFaults, ModuleThatThrowsStopsTheRobotWhenConfiguredTo) {
  std::string text = test::read_file(test::kHipConfig);
  text.replace(text.find("../nao.urdf"), 11, STRIDE_SOURCE_DIR "/scenes/robots/nao/nao.urdf");
  text.replace(text.find("on_module_error=\"continue\""), 26, "on_module_error=\"stop\"");
  text.replace(text.find("</controller>"), 13,
               "<at time=\"0.5s\"><parameter module=\"PatternWalk\" field=\"z_max\" "
               "value=\"0.5\"/></at></controller>");
  const std::string config = ChildProcess::scratch("stops.xml");
  std::ofstream(config) << text;
  const std::string socket = ChildProcess::scratch("stops.sock");
  ChildProcess sim({test::kStride, "run", test::kHipScene, "--seconds", "5", "--lola", socket},
                   "stops_sim");
  ASSERT_TRUE(test::wait_for_file(socket, 60)) << sim.err();
  ChildProcess robot({test::kStrideRobot, "--config", config, "--lola", socket}, "stops_robot");
  EXPECT_EQ(robot.wait_for(60), 3) << robot.err();
  EXPECT_NE(robot.err().find("(holding the last safe command; stopping)"), std::string::npos)
      << robot.err();
  EXPECT_EQ(sim.wait_for(60), 0) << sim.err();  // the simulator goes on without its client
  EXPECT_NE(sim.err().find("client lost (it closed the socket)"), std::string::npos) << sim.err();
}

}  // namespace
}  // namespace stride
