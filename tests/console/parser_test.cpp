// The pure parser: words, statements, the command table's checks, suggestions and comparisons.
#include <gtest/gtest.h>

#include "console/interpreter/command_parser.hpp"
#include "console/interpreter/command_table.hpp"
#include "console/interpreter/edit_distance.hpp"
#include "console/interpreter/tokenizer.hpp"
#include "console/interpreter/values.hpp"
#include "robot/core/error.hpp"

namespace stride::console {
namespace {

std::string error_of(std::string_view line) {
  try {
    parse_command(line);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Tokenizer, SplitsOnBlanksKeepsQuotedTextAndStopsAtComments) {
  EXPECT_EQ(tokenize("  set  module:Stand   knee_pitch=0.5\t"),
            (std::vector<std::string>{"set", "module:Stand", "knee_pitch=0.5"}));
  EXPECT_EQ(tokenize("echo \"a b\" c # not this"), (std::vector<std::string>{"echo", "a b", "c"}));
  EXPECT_EQ(tokenize("echo \"say \\\"hi\\\"\""), (std::vector<std::string>{"echo", "say \"hi\""}));
  EXPECT_EQ(tokenize("a#b"), (std::vector<std::string>{"a#b"}));  // '#' only at a word start
  EXPECT_TRUE(tokenize("   # comment").empty());
  EXPECT_THROW(tokenize("echo \"open"), Error);
}

TEST(Tokenizer, StatementsSplitAtSemicolonsOutsideQuotes) {
  EXPECT_EQ(split_statements("run 1; expect robot.fell == false ;; echo \"a;b\""),
            (std::vector<std::string>{"run 1", "expect robot.fell == false", "echo \"a;b\""}));
  EXPECT_TRUE(split_statements(" ; ").empty());
}

TEST(EditDistance, ClassicValuesAndSuggestions) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("same", "same"), 0u);
  EXPECT_EQ(nearest("exepct", command_names()), "expect");
  EXPECT_EQ(nearest("rnu", command_names()), "run");
  EXPECT_EQ(nearest("completelydifferent", command_names()), "");
}

TEST(Parser, BlankAndCommentLinesAreNoCommand) {
  EXPECT_TRUE(parse_command("").name.empty());
  EXPECT_TRUE(parse_command("# run 5").name.empty());
}

TEST(Parser, AcceptsTheVocabulary) {
  for (const char* line : {"help",
                           "help log",
                           "load a.xml",
                           "reset",
                           "run",
                           "run 2.5",
                           "step",
                           "step 10",
                           "pause",
                           "realtime off",
                           "get representation:JointRequest.position[3]",
                           "get module:Stand ?",
                           "get robot.torso.z",
                           "set module:Stand knee_pitch=0.5 hip_pitch=-0.2",
                           "mr ?",
                           "mr JointRequest ?",
                           "mr JointRequest default",
                           "dr ?",
                           "dr x on",
                           "watch robot.torso.z sim.time every 10",
                           "watch off",
                           "plot robot.torso.z to a.csv",
                           "plot stop",
                           "log start a.log",
                           "log stop",
                           "log load a.log",
                           "log goto 3",
                           "log export a.csv FrameInfo.time",
                           "log replay",
                           "report",
                           "report r.json",
                           "push torso 1 0 0 0.1",
                           "mv 0 0 0.3",
                           "mv 0 0 0.3 1.5",
                           "sn quantise on",
                           "expect robot.fell == false",
                           "expect robot.torso.z ~= 0.3 0.01",
                           "wait until sim.time >= 1",
                           "wait until sim.time >= 1 timeout 3",
                           "call x.con",
                           "echo",
                           "echo a b",
                           "quit"}) {
    EXPECT_NO_THROW(parse_command(line)) << line;
  }
  const Command c = parse_command("set module:Stand knee_pitch=0.5");
  EXPECT_EQ(c.name, "set");
  EXPECT_EQ(c.args, (std::vector<std::string>{"module:Stand", "knee_pitch=0.5"}));
}

TEST(Parser, UnknownCommandsSuggestTheNearest) {
  EXPECT_EQ(error_of("exepct robot.fell == false"),
            "unknown command 'exepct'; did you mean 'expect'?");
  EXPECT_EQ(error_of("frobnicate"), "unknown command 'frobnicate' (try help)");
}

TEST(Parser, WrongArityNamesTheUsage) {
  EXPECT_EQ(error_of("push torso 1 2"),
            "push: expected 5 argument(s), got 3; usage: push <body> <fx> <fy> <fz> <seconds>");
  EXPECT_EQ(error_of("mv 1"),
            "mv: expected 3 to 4 argument(s), got 1; usage: mv <x> <y> <z> [yaw]");
  EXPECT_EQ(error_of("set module:Stand"),
            "set: expected at least 2 argument(s), got 1; usage: set <key> <field>=<value>... | "
            "set representation:X unchanged");
}

TEST(Parser, BadArgumentsAreNamed) {
  EXPECT_EQ(error_of("run fast"),
            "run: seconds: expected a number, got 'fast'; usage: run [seconds]");
  EXPECT_EQ(error_of("run -1"), "run: seconds: -1 s outside [0, 1e+06]; usage: run [seconds]");
  EXPECT_EQ(error_of("step 0"), "step: frames: 0 is outside [1, 1000000000]; usage: step [frames]");
  EXPECT_EQ(error_of("realtime maybe"),
            "realtime: switch: expected on or off, got 'maybe'; usage: realtime on|off");
  EXPECT_NE(error_of("get JointRequest").find("'JointRequest' is not a key"), std::string::npos);
  EXPECT_NE(error_of("set module:Stand knee_pitch").find("expected <field>=<value>"),
            std::string::npos);
  EXPECT_NE(error_of("expect robot.fell === 1").find("expected an operator"), std::string::npos);
  EXPECT_NE(error_of("push torso 1 nan 0 1").find("fy: expected a number"), std::string::npos);
  EXPECT_NE(error_of("sn gravity on").find("expected noise, delay or quantise"), std::string::npos);
  EXPECT_NE(error_of("log rewind").find("unknown log action 'rewind'"), std::string::npos);
  EXPECT_NE(error_of("log goto -2").find("frame: -2 is outside"), std::string::npos);
  EXPECT_NE(error_of("wait for sim.time > 1").find("expected 'until'"), std::string::npos);
  EXPECT_NE(error_of("wait until sim.time > 1 timeout").find("timeout <seconds>"),
            std::string::npos);
  EXPECT_NE(error_of("watch every 3").find("at least one key"), std::string::npos);
  EXPECT_NE(error_of("mr JointRequest").find("give a module, default or ?"), std::string::npos);
}

TEST(Values, ComparisonsFollowTheirOperators) {
  EXPECT_TRUE(compare("0.305", Op::Near, "0.3", 0.01));
  EXPECT_FALSE(compare("0.32", Op::Near, "0.3", 0.01));
  EXPECT_TRUE(compare("2", Op::Greater, "1.5", 0));
  EXPECT_FALSE(compare("1.5", Op::Less, "1.5", 0));
  EXPECT_TRUE(compare("1.5", Op::LessEqual, "1.5", 0));
  EXPECT_TRUE(compare("false", Op::Equal, "0", 0));
  EXPECT_TRUE(compare("true", Op::NotEqual, "false", 0));
  EXPECT_TRUE(compare("Stand", Op::Equal, "Stand", 0));
  EXPECT_THROW(compare("Stand", Op::Less, "Sit", 0), Error);
  EXPECT_EQ(parse_integer("12", "n", 0, 20), 12);
  EXPECT_THROW(parse_integer("12x", "n", 0, 20), Error);
  EXPECT_THROW(parse_number("inf", "x"), Error);
  EXPECT_DOUBLE_EQ(parse_number("+2.5e-1", "x"), 0.25);
}

}  // namespace
}  // namespace stride::console
