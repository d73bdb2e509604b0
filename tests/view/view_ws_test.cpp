// `stride view <scene>` over its WebSocket: hello, scene and frame on joining; a `cmd` runs a
// console line and the next frame shows its effect; watched keys come back as samples.
#include <gtest/gtest.h>

#include "simulator/simulation.hpp"
#include "tests/view/view_client.hpp"

namespace stride::view_test {
namespace {

class ViewWs : public ::testing::Test {
 protected:
  void SetUp() override {
    view_ = std::make_unique<ViewProcess>(std::vector<std::string>{scene_path(kScene)}, "127.0.0.1",
                                          "ws");
    ASSERT_NE(view_->port(), 0) << view_->out() << view_->err();
  }
  static constexpr const char* kScene = "nao_stand_controlled.xml";
  // A clean end: exit code 0 on SIGTERM (under the sanitizers: no leak, no error report).
  void TearDown() override {
    if (view_) {
      EXPECT_EQ(view_->stop(), 0) << view_->err();
    }
  }
  std::unique_ptr<ViewProcess> view_;
};

TEST_F(ViewWs, HelloSceneAndFrameArriveWithTheScenesLinks) {
  const auto sim = sim::Simulation::from_file(scene_path(kScene));
  WsClient page(view_->port());
  ASSERT_TRUE(page.connected());
  const Json hello = page.read_type("hello");
  ASSERT_TRUE(hello.is_object());
  EXPECT_EQ(hello["mode"], "sim");
  EXPECT_EQ(hello["paused"], true);
  EXPECT_EQ(hello["realtime"], false);
  EXPECT_NEAR(hello["period"].get<double>(), sim->robot(0).period(), 1e-12);
  const Json scene = page.read_type("scene");
  ASSERT_TRUE(scene.is_object());
  ASSERT_EQ(scene["robots"].size(), 1u);
  const auto& model = sim->robot(0).model();
  ASSERT_EQ(scene["robots"][0]["links"].size(), model.links.size());
  EXPECT_EQ(scene["robots"][0]["links"][0]["name"], model.links[0].name);
  const Json frame = page.read_type("frame");
  ASSERT_TRUE(frame.is_object());
  EXPECT_EQ(frame["t"], 0.0);
  EXPECT_EQ(frame["dropped"], 0);
  ASSERT_EQ(frame["robots"][0]["links"].size(), model.links.size());
  // The torso stands where the scene puts it: the frame's pose is the world's.
  const Eigen::Vector3d root = sim->robot(0).body().link_pose(model.root_link).translation();
  const Json& pose = frame["robots"][0]["links"][model.root_link];
  EXPECT_NEAR(pose[0].get<double>(), root.x(), 1e-6);
  EXPECT_NEAR(pose[2].get<double>(), root.z(), 1e-6);
}

TEST_F(ViewWs, StepTenAdvancesTheFrameByTenPhysicsSteps) {
  const auto sim = sim::Simulation::from_file(scene_path(kScene));
  const double dt = sim->scene().physics.step;
  WsClient page(view_->port());
  ASSERT_TRUE(page.read_type("frame").is_object());
  const Json reply = command(page, 7, "step 10");
  ASSERT_TRUE(reply.is_object());
  EXPECT_EQ(reply["ok"], true) << reply.dump();
  const Json frame = page.read_type("frame");
  ASSERT_TRUE(frame.is_object());
  EXPECT_NEAR(frame["t"].get<double>(), 10 * dt, 1e-12);
  EXPECT_EQ(frame["running"], false);
  const Json echo = command(page, 8, "echo hello view");
  EXPECT_EQ(echo["output"], "hello view\n");
  const Json bad = command(page, 9, "stpe 3");
  EXPECT_EQ(bad["ok"], false);
  EXPECT_FALSE(bad["error"].get<std::string>().empty());
}

TEST_F(ViewWs, WatchedTimeComesBackIncreasingWhileRunning) {
  WsClient page(view_->port());
  ASSERT_TRUE(page.read_type("frame").is_object());
  page.send(R"({"op":"watch","keys":["representation:FrameInfo.time"]})");
  ASSERT_EQ(command(page, 1, "run")["ok"], true);
  std::vector<double> times;
  const auto end = std::chrono::steady_clock::now() + 20s;
  while (times.size() < 50 && std::chrono::steady_clock::now() < end) {
    const Json f = page.read_type("frame", 5s);
    ASSERT_TRUE(f.is_object());
    ASSERT_EQ(f["samples"]["keys"][0], "representation:FrameInfo.time");
    for (const auto& row : f["samples"]["rows"]) {
      ASSERT_EQ(row.size(), 2u);
      times.push_back(row[1].get<double>());
    }
  }
  ASSERT_GE(times.size(), 50u);
  for (std::size_t i = 1; i < times.size(); ++i) EXPECT_GT(times[i], times[i - 1]) << i;
  EXPECT_EQ(command(page, 2, "pause")["ok"], true);
  page.send(R"({"op":"watch","keys":["robot.name"]})");
  const Json error = page.read_type("error");
  EXPECT_NE(error["error"].get<std::string>().find("robot.name"), std::string::npos);
}

TEST_F(ViewWs, AFallIsAnEventAndTheFrameSaysSo) {
  WsClient page(view_->port());
  ASSERT_TRUE(page.read_type("frame").is_object());
  ASSERT_EQ(command(page, 1, "push torso 150 0 0 0.2")["ok"], true);
  page.send(R"({"op":"cmd","id":2,"line":"step 3000"})");  // events come while it runs
  bool fell = false;
  Json event;
  const auto end = std::chrono::steady_clock::now() + 20s;
  while ((!fell || event.is_null()) && std::chrono::steady_clock::now() < end) {
    const auto text = page.read(10s);
    ASSERT_TRUE(text.has_value());
    const Json m = Json::parse(*text);
    if (m["type"] == "event" && m["kind"] == "fall") event = m;
    if (m["type"] == "frame" && m["robots"][0]["fell"] == true) fell = true;
  }
  EXPECT_TRUE(fell);
  ASSERT_TRUE(event.is_object());
  EXPECT_EQ(event["text"], "nao fell");
  EXPECT_GT(event["t"].get<double>(), 0.0);
}

}  // namespace
}  // namespace stride::view_test
