// `stride help <topic>` and `help <topic>` in the console answer the questions people ask first
// (speed, push, mujoco, realtime, remote, view, log), each answer with an example; the examples
// typed into the console run.
#include <gtest/gtest.h>

#include <map>

#include "console/interpreter/help_topics.hpp"
#include "tests/cli/stride_process.hpp"

namespace stride {
namespace {

using test_support::run_stride;
using test_support::TempFolder;

// What each answer must say: the thing to type.
const std::map<std::string, std::vector<std::string>> kMustSay = {
    {"speed", {"PatternWalk.preset=fast", "V_min", "T_stride", "before"}},
    {"push", {"push torso 0 20 0 0.1", "newtons", "<push robot"}},
    {"mujoco", {"engine=\"mujoco\"", "--physics engine=mujoco", "libmujoco-dev"}},
    {"realtime", {"realtime on", "realtime off"}},
    {"remote", {"--debug", "--connect 127.0.0.1:7000", "--token-file"}},
    {"view", {"stride view", "--connect", "--log"}},
    {"log", {"log start", "log replay", "log save"}},
};

TEST(HelpTopics, EveryTopicAnswersFromTheCommandLineAndTheConsole) {
  TempFolder dir;
  ASSERT_EQ(console::help_topics().size(), kMustSay.size());
  for (const auto& topic : console::help_topics()) {
    const std::string name(topic.name);
    ASSERT_TRUE(kMustSay.count(name)) << name;
    const auto cli = run_stride({"help", name}, dir.path());
    EXPECT_EQ(cli.exit_code, 0) << name << ": " << cli.err;
    EXPECT_EQ(cli.out.rfind("topic " + name + ":\n" + std::string(topic.answer), 0), 0u)
        << "stride help " << name << " printed:\n"
        << cli.out;
    EXPECT_NE(cli.out.find("example:"), std::string::npos) << name;
    for (const std::string& phrase : kMustSay.at(name))
      EXPECT_NE(cli.out.find(phrase), std::string::npos) << name << " lacks " << phrase;
    const auto repl = run_stride({"-c", "help " + name}, dir.path());
    EXPECT_EQ(repl.exit_code, 0) << name << ": " << repl.err;
    EXPECT_NE(repl.out.find(std::string(topic.answer)), std::string::npos)
        << "help " << name << " in the console printed:\n"
        << repl.out;
  }
}

TEST(HelpTopics, CommandsAreStillListedAfterTheTopicAndUnknownWordsSaySo) {
  TempFolder dir;
  const auto push = run_stride({"help", "push"}, dir.path());
  EXPECT_LT(push.out.find("topic push:"), push.out.find("push <body> <fx> <fy> <fz> <seconds>"));
  const auto all = run_stride({"help"}, dir.path());
  EXPECT_NE(all.out.find("topics (help <topic>): speed push mujoco realtime remote view log"),
            std::string::npos);
  const auto none = run_stride({"help", "zzzqqq"}, dir.path());
  EXPECT_NE(none.out.find("nothing matches 'zzzqqq'"), std::string::npos);
  EXPECT_EQ(none.out.find("topic "), std::string::npos);
}

// The console lines `help speed` and `help push` give, typed on the walking scene: they run, and
// the speed one changes the walk's speed.
TEST(HelpTopics, ConsoleExamplesRun) {
  TempFolder dir;
  const std::string scene = test_support::source_file("scenes/walking/open_loop_medium.xml");
  const auto speed = run_stride({"-c",
                                 "reset; set module:PatternWalk V_min=0.12 V_max=0.13; run 0.1; "
                                 "expect module:PatternWalk.V_max == 0.13; push torso 0 20 0 0.1; "
                                 "run 2; expect robot.fell == 0",
                                 scene},
                                dir.path());
  EXPECT_EQ(speed.exit_code, 0) << speed.out << speed.err;
  EXPECT_NE(speed.out.find("ok module:PatternWalk.V_max = 0.13"), std::string::npos);
  EXPECT_NE(speed.out.find("ok robot.fell = false"), std::string::npos);  // 2 N s: upright
  const std::string answer(console::help_topic_text("speed"));
  EXPECT_NE(answer.find("reset; set module:PatternWalk V_min=0.12 V_max=0.13; run"),
            std::string::npos);
  EXPECT_NE(console::help_topic_text("push").find("push torso 0 20 0 0.1"), std::string::npos);
}

}  // namespace
}  // namespace stride
