// A paused remote view (`stride view --connect`, the page's `pause`) sends the page no frames while
// the robot goes on; `run` follows the robot again, from where its clock is then.
#include <gtest/gtest.h>

#include <thread>

#include "tests/debug/served_process.hpp"
#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

// Waits `d`, then runs `line` and counts the frames that came before its reply (a read that
// times out ends the page's connection, so the reply marks the window's end; the frame every
// reply brings is taken too); the last one's t in `t`. -1 when no reply came.
int frames_within(WsClient& page, std::chrono::milliseconds d, int id, double& t,
                  const std::string& line = "get representation:FrameInfo.frame") {
  std::this_thread::sleep_for(d);
  page.send(Json{{"op", "cmd"}, {"id", id}, {"line", line}}.dump());
  int frames = 0;
  for (int i = 0; i < 100000; ++i) {
    const auto text = page.read(30s);
    if (!text) return -1;
    const Json m = Json::parse(*text, nullptr, false);
    if (!m.is_object()) continue;
    if (m.value("type", "") == "reply" && m.value("id", -1) == id)  // then the reply's own frame
      return page.read_type("frame").is_object() ? frames : -1;
    if (m.value("type", "") != "frame") continue;
    ++frames;
    t = m.value("t", -1.0);
  }
  return -1;
}

TEST(ViewConnect, APausedRemoteViewGetsNoFramesAndRunFollowsAgain) {
  test::Served served("view_pause", false, 90);
  ASSERT_NE(served.at.port, 0) << served.process.err();
  ViewProcess view({"--connect", served.at.text()}, "127.0.0.1", "remote");
  ASSERT_NE(view.port(), 0) << view.out() << view.err();
  WsClient page(view.port());
  ASSERT_TRUE(page.read_type("hello").is_object());
  double t = -1;
  EXPECT_GT(frames_within(page, 1500ms, 1, t), 10);  // following the robot: about 60 a second
  const Json paused = command(page, 2, "pause");
  ASSERT_EQ(paused.value("ok", false), true) << paused.dump();
  const Json shown = page.read_type("frame");  // the pause reply's own frame
  const double paused_t = shown.value("t", -1.0);
  ASSERT_GT(paused_t, 0) << shown.dump();
  EXPECT_EQ(shown.value("running", true), false);
  double late_t = -1;
  EXPECT_EQ(frames_within(page, 2000ms, 4, late_t), 0) << "at t=" << late_t;
  const Json running = command(page, 5, "run");
  ASSERT_EQ(running.value("ok", false), true) << running.dump();
  double resumed_t = -1;
  EXPECT_GT(frames_within(page, 1500ms, 6, resumed_t), 10);
  EXPECT_GT(resumed_t, paused_t + 1.5) << paused_t;  // the robot went on; the view follows it
}

}  // namespace
}  // namespace stride::view_test
