// Help that finds things: every subcommand and console command has its --help, a word finds a
// command named so first, then whole words, then parts of words; the key namespaces are listed.
#include <gtest/gtest.h>

#include <sstream>

#include "console/cli/help.hpp"
#include "console/interpreter/command_table.hpp"
#include "console/interpreter/help_search.hpp"

namespace stride {
namespace {

std::string help_of(const std::string& name) {
  std::ostringstream out;
  EXPECT_TRUE(cli::print_command_help(name, out)) << name;
  return out.str();
}

TEST(Help, EveryCommandHasItsUsage) {
  for (const auto& s : cli::subcommands())
    EXPECT_EQ(help_of(std::string(s.name)).rfind("usage: stride " + std::string(s.summary), 0), 0u)
        << s.name;
  for (const auto& c : console::command_table())
    EXPECT_NE(help_of(std::string(c.name)).find(std::string(c.usage)), std::string::npos) << c.name;
  // `run` is both: the subcommand's usage, then the console command's.
  const std::string run = help_of("run");
  EXPECT_LT(run.find("usage: stride run <scene>"), run.find("console command run [seconds]"));
  std::ostringstream none;
  EXPECT_FALSE(cli::print_command_help("frobnicate", none));
}

TEST(Help, WholeWordsBeforePartsOfWords) {
  const std::vector<console::HelpEntry> entries = {
      {"plot", "record values; stop writes CSV + PNG, a log of them"},
      {"log", "record, load and replay logs"},
      {"watch", "print values every N steps while running"},
      {"logging", "nothing"}};
  EXPECT_EQ(console::find_help(entries, "log"), (std::vector<std::size_t>{1}));  // its name
  EXPECT_EQ(console::find_help(entries, "record"), (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(console::find_help(entries, "steps"), (std::vector<std::size_t>{2}));
  EXPECT_EQ(console::find_help(entries, "step"), (std::vector<std::size_t>{2}));  // a part
  EXPECT_EQ(console::find_help(entries, "logs"), (std::vector<std::size_t>{1}));
  EXPECT_TRUE(console::find_help(entries, "xyz").empty());
}

TEST(Help, EveryKeyNamespaceIsListed) {
  const std::string keys = console::help_text("keys");
  for (const char* k : {"representation:X", "module:X", "provider:X", "override:X", "debug:",
                        "sim.time", "robot.name", "robot.torso", "robot.com", "log.frames"})
    EXPECT_NE(keys.find(k), std::string::npos) << k;
  std::ostringstream all;
  EXPECT_EQ(cli::help_main({}, all), 0);
  EXPECT_NE(all.str().find("console commands"), std::string::npos);
  EXPECT_NE(all.str().find("provider:X"), std::string::npos);
  EXPECT_NE(all.str().find("exit codes: 0 done; 1 it ran and failed"), std::string::npos);
}

}  // namespace
}  // namespace stride
