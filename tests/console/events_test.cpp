// Issue 49 point 2: events a person must not miss print one line each in the console, whatever
// debug requests are on: a fall (once, not every frame), a held override whose provider is
// swapped, a joint request the guard limited. Point 7: `push` to a link that is not there lists
// the robot's links.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "console/interpreter/interpreter.hpp"
#include "console/target/local_target.hpp"
#include "robot/core/error.hpp"

namespace stride::console {
namespace {

const std::string kScene = STRIDE_SOURCE_DIR "/scenes/nao_stand_controlled.xml";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

class EventsTest : public ::testing::Test {
 protected:
  void SetUp() override { console.execute("load " + kScene); }
  std::string run(const std::string& line) {
    out.str("");
    console.execute(line);
    return out.str();
  }
  LocalTarget target;
  std::ostringstream out;
  Interpreter console{target, out};
};

TEST_F(EventsTest, AFallIsAnnouncedOnceWithoutAnyDebugRequest) {
  run("run 0.5");
  EXPECT_EQ(target.get("robot.fell"), "false");
  run("push torso 0 250 0 0.2");
  const std::string text = run("run 4");
  ASSERT_EQ(target.get("robot.fell"), "true");
  EXPECT_EQ(count(text, "event: FELL at t="), 1) << text;
  EXPECT_NE(text.find("past fall_tilt 0.80"), std::string::npos) << text;
  // One line: nothing of it continues onto the next.
  const auto at = text.find("event: FELL");
  EXPECT_EQ(text.substr(0, at).rfind('\n') + 1, text.rfind("t=", at)) << text;
}

TEST_F(EventsTest, SwappingTheProviderOfAHeldRepresentationIsSaid) {
  run("set representation:JointRequest position[HeadYaw]=0.3");
  run("mr JointRequest PositionBalance");
  const std::string text = run("step");
  EXPECT_EQ(count(text,
                  "event: provider of JointRequest swapped Stand -> PositionBalance, but a "
                  "held override still sets it every frame"),
            1)
      << text;
  EXPECT_EQ(run("step"), "");  // said once
}

TEST_F(EventsTest, ALimitedJointRequestIsSaidWhenItStarts) {
  run("run 0.1");
  run("set representation:JointRequest position[HeadYaw]=3");  // beyond HeadYaw's 2.0857 rad
  const std::string text = run("run 0.5");
  EXPECT_EQ(count(text, "event: joint request limited"), 1) << text;
}

TEST_F(EventsTest, PushToAnUnknownLinkListsTheLinks) {
  try {
    run("push foo 0 10 0 0.1");
    FAIL() << "accepted";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("no link named 'foo'"), std::string::npos) << m;
    EXPECT_NE(m.find("its links: torso, Neck, Head"), std::string::npos) << m;
    EXPECT_NE(m.find("RAnkle"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace stride::console
