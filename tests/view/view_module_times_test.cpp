// Module times reach a page only while one asks for them (op times: its module graph shows), so a
// robot's loop copies its ModuleTimes every frame only then; both for a local scene and a robot.
#include <gtest/gtest.h>

#include <thread>

#include "tests/debug/served_process.hpp"
#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

// The `times` of the frame that a command's reply brings (after `line` ran).
Json times_after(WsClient& page, int id, const std::string& line) {
  const Json reply = command(page, id, line);
  EXPECT_EQ(reply.value("ok", false), true) << reply.dump();
  const Json frame = page.read_type("frame");
  return frame.is_object() ? frame.value("times", Json()) : Json();
}

TEST(ViewModuleTimes, ALocalScenesFramesCarryThemOnlyWhileAPageAsks) {
  ViewProcess view({scene_path("nao_stand_controlled.xml")}, "127.0.0.1", "ws");
  ASSERT_NE(view.port(), 0) << view.out() << view.err();
  WsClient page(view.port());
  ASSERT_TRUE(page.read_type("frame").is_object());
  const Json off = times_after(page, 1, "step 30");
  ASSERT_TRUE(off.is_object()) << off.dump();
  EXPECT_TRUE(off.empty()) << off.dump();
  page.send(R"({"op":"times","on":true})");
  const Json on = times_after(page, 2, "step 30");
  ASSERT_TRUE(on.is_object());
  ASSERT_FALSE(on.empty());
  for (const auto& [module, ms] : on.items()) {
    EXPECT_FALSE(module.empty());
    EXPECT_GE(ms.get<double>(), 0.0) << module;
  }
  page.send(R"({"op":"times","on":false})");
  EXPECT_TRUE(times_after(page, 3, "step 30").empty());
  page.send(R"({"op":"times","on":"yes"})");
  const Json error = page.read_type("error");
  EXPECT_EQ(error.value("error", ""), "ws message: \"on\" should be true or false");
}

TEST(ViewModuleTimes, ARobotStreamsThemOnlyWhileAPageAsks) {
  test::Served served("view_times", false, 90);
  ASSERT_NE(served.at.port, 0) << served.process.err();
  ViewProcess view({"--connect", served.at.text()}, "127.0.0.1", "remote");
  ASSERT_NE(view.port(), 0) << view.out() << view.err();
  WsClient page(view.port());
  ASSERT_TRUE(page.read_type("hello").is_object());
  std::this_thread::sleep_for(500ms);
  EXPECT_TRUE(times_after(page, 1, "echo off").empty());
  page.send(R"({"op":"times","on":true})");
  // The next frames the view follows carry them: wait for one, bounded.
  Json on;
  for (int i = 0; i < 200 && (!on.is_object() || on.empty()); ++i) {
    const Json frame = page.read_type("frame");
    ASSERT_TRUE(frame.is_object());
    on = frame.value("times", Json());
  }
  ASSERT_TRUE(on.is_object());
  EXPECT_FALSE(on.empty());
  const Json stream = command(page, 2, "get representation:ModuleTimes.ns");
  EXPECT_EQ(stream.value("ok", false), true) << stream.dump();
}

}  // namespace
}  // namespace stride::view_test
