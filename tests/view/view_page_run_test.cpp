// One page's `run <seconds>` holds no other page: it runs in the background, the other pages'
// commands are answered while it runs, a `pause` from any page ends it early, and the page that
// asked is answered when its run ends, where it ended.
#include <gtest/gtest.h>

#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

double time_of(const Json& reply) {
  return std::stod(reply.value("output", std::string("nan")));
}

TEST(ViewPageRun, OnePagesRunHoldsNoOtherPagesCommands) {
  ViewProcess view({scene_path("nao_stand_controlled.xml")});
  ASSERT_TRUE(view.port()) << view.err();
  WsClient a(view.port()), b(view.port());
  ASSERT_TRUE(a.connected() && b.connected());
  ASSERT_EQ(command(b, 1, "realtime on")["ok"], true);  // 5 s of the robot's time take 5 s
  const auto start = std::chrono::steady_clock::now();
  a.send(Json{{"op", "cmd"}, {"id", 7}, {"line", "run 5"}}.dump());
  // Page b is answered within a second while a's run goes on, at a time the run has reached.
  std::this_thread::sleep_for(300ms);
  const Json t1 = command(b, 2, "get representation:FrameInfo.time", 2s);
  ASSERT_TRUE(t1.is_object());
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1500ms);
  const double mid = time_of(t1);
  EXPECT_GT(mid, 0.1);
  EXPECT_LT(mid, 2.0);
  // A second run is refused while one runs; `pause` from b ends a's run early.
  const Json twice = command(b, 3, "run 1", 2s);
  EXPECT_EQ(twice["ok"], false);
  EXPECT_NE(twice.value("error", "").find("running in the background"), std::string::npos)
      << twice.dump();
  ASSERT_EQ(command(b, 4, "pause", 2s)["ok"], true);
  const Json done = a.read_type("reply", 3s);
  ASSERT_TRUE(done.is_object());
  EXPECT_EQ(done["id"], 7);
  EXPECT_EQ(done["ok"], true);
  const std::string said = done["output"];
  EXPECT_NE(said.find("paused before the run's end"), std::string::npos) << said;
  EXPECT_LT(std::chrono::steady_clock::now() - start, 4s);
  // Run to its end: the reply comes when the robot's time has gone exactly that far.
  ASSERT_EQ(command(b, 5, "realtime off")["ok"], true);
  const double from = time_of(command(b, 6, "get representation:FrameInfo.time"));
  const Json full = command(a, 8, "run 0.5");
  ASSERT_TRUE(full.is_object());
  EXPECT_EQ(full["ok"], true);
  EXPECT_EQ(full["output"].get<std::string>().find("before"), std::string::npos);
  const double to = time_of(command(b, 9, "get representation:FrameInfo.time"));
  EXPECT_NEAR(to - from, 0.5, 0.011);  // within a control frame
}

}  // namespace
}  // namespace stride::view_test
