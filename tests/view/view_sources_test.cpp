// `stride view --connect` (a running `stride run --debug`) and `stride view --log` (a recorded
// log, browsed with `log goto`): the robot drawn from its joint angles and IMU, feet on the ground.
#include <gtest/gtest.h>

#include "robot/core/data_dir.hpp"
#include "robot/model/urdf_loader.hpp"
#include "tests/debug/served_process.hpp"
#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

// The lowest link origin of a frame's robot (the feet's are above their soles).
double lowest_z(const Json& frame) {
  double z = 1e9;
  for (const auto& pose : frame["robots"][0]["links"]) z = std::min(z, pose[2].get<double>());
  return z;
}

TEST(ViewConnect, ARemoteRobotIsDrawnFromItsSensorsAndFollowed) {
  test::Served served("view_remote", false, 90);
  ASSERT_NE(served.at.port, 0) << served.process.err();
  ViewProcess view({"--connect", served.at.text()}, "127.0.0.1", "remote");
  ASSERT_NE(view.port(), 0) << view.out() << view.err();
  const auto nao = model::load_urdf(data_file("scenes/robots/nao/nao.urdf"));
  WsClient page(view.port());
  const Json hello = page.read_type("hello");
  ASSERT_TRUE(hello.is_object());
  EXPECT_EQ(hello["mode"], "remote");
  const Json scene = page.read_type("scene");
  ASSERT_EQ(scene["robots"].size(), 1u);
  EXPECT_EQ(scene["robots"][0]["links"].size(), nao.links.size());
  EXPECT_TRUE(scene["statics"].empty());
  page.send(R"({"op":"watch","keys":["representation:FrameInfo.time"]})");
  double first = -1, last = -1;
  std::size_t samples = 0;
  const auto end = std::chrono::steady_clock::now() + 30s;
  while (samples < 30 && std::chrono::steady_clock::now() < end) {
    const Json f = page.read_type("frame", 10s);
    ASSERT_TRUE(f.is_object());
    if (f["robots"].empty()) continue;
    ASSERT_EQ(f["robots"][0]["links"].size(), nao.links.size());
    EXPECT_GT(lowest_z(f), -0.001);  // standing on the ground, not under it
    EXPECT_LT(lowest_z(f), 0.06);
    EXPECT_FALSE(f["robots"][0]["support"].empty());
    if (first < 0) first = f["t"];
    last = f["t"];
    for (const auto& row : f["samples"]["rows"]) {
      EXPECT_EQ(row.size(), 2u);
      ++samples;
    }
  }
  EXPECT_GE(samples, 30u);
  EXPECT_GT(last, first);  // the robot's clock went on and the view followed it
  const Json name = command(page, 1, "get representation:FrameInfo.period");
  EXPECT_EQ(name["ok"], true);
  EXPECT_NE(name["output"].get<std::string>().find("0.01"), std::string::npos) << name.dump();
}

TEST(ViewLog, ALogIsBrowsedFrameByFrame) {
  const auto dir = test_support::fresh_path("view", "log_recorded");
  std::filesystem::create_directories(dir);
  const std::string log = (dir / "walk.log").string();
  const pid_t run =
      test_support::start_process({stride_binary(), "run", scene_path("nao_stand_controlled.xml"),
                                   "--seconds", "1", "--log", log},
                                  dir / "run_out.txt", dir / "run_err.txt");
  ASSERT_EQ(test_support::finish_process(run), 0) << test_support::read_text(dir / "run_err.txt");
  ViewProcess view({"--log", log}, "127.0.0.1", "log");
  ASSERT_NE(view.port(), 0) << view.out() << view.err();
  WsClient page(view.port());
  const Json hello = page.read_type("hello");
  ASSERT_TRUE(hello.is_object()) << view.out() << view.err();
  EXPECT_EQ(hello["mode"], "log");
  const std::size_t frames = hello["log_frames"];
  page.send(R"({"op":"watch","keys":["representation:FrameInfo.frame"]})");
  EXPECT_NEAR(static_cast<double>(frames), 100, 1);
  // The row of the shown frame rides on a frame with log_frame 50, sent before or after the reply.
  page.send(R"({"op":"cmd","id":1,"line":"log goto 50"})");
  Json f, row_frame, goto_reply;
  for (int i = 0; i < 200 && (goto_reply.is_null() || row_frame.is_null()); ++i) {
    const auto text = page.read(10s);
    ASSERT_TRUE(text.has_value()) << view.err();
    const Json m = Json::parse(*text, nullptr, false);
    if (m.value("type", "") == "reply" && m.value("id", -1) == 1) goto_reply = m;
    if (m.value("type", "") != "frame" || m["log_frame"] != 50) continue;
    f = m;
    if (!m["samples"]["rows"].empty()) row_frame = m;
  }
  ASSERT_EQ(goto_reply["ok"], true) << goto_reply.dump();
  ASSERT_TRUE(f.is_object());
  ASSERT_EQ(f["robots"].size(), 1u);
  EXPECT_GT(lowest_z(f), -0.001);
  EXPECT_NEAR(f["t"].get<double>(), 0.5, 0.011);  // the log's own clock at frame 50
  ASSERT_TRUE(row_frame.is_object()) << "no frame of log frame 50 carried its sample row";
  ASSERT_EQ(row_frame["samples"]["rows"].size(), 1u);  // the shown frame's values, at its time
  EXPECT_EQ(row_frame["samples"]["rows"][0][0], row_frame["t"]);
  EXPECT_EQ(row_frame["samples"]["rows"][0][1], 50);
  EXPECT_GT(f["wall"].get<double>(), 1.7e12);
  const Json t = command(page, 2, "get representation:FrameInfo.frame");
  EXPECT_NE(t["output"].get<std::string>().find("50"), std::string::npos) << t.dump();
  EXPECT_EQ(command(page, 3, "log goto 100000")["ok"], false);
}

}  // namespace
}  // namespace stride::view_test
