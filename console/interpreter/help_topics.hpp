#pragma once
// `help <topic>` and `stride help <topic>`: short answers to the questions people ask first (how do
// I change the walking speed, push the robot, use MuJoCo, ...), each with an example to copy.
#include <span>
#include <string>
#include <string_view>

namespace stride::console {

struct HelpTopic {
  std::string_view name;    // the word typed after help, e.g. "speed"
  std::string_view answer;  // a few lines ending in an example; every line ends in '\n'
};

std::span<const HelpTopic> help_topics();

// "topic <name>:\n" and its answer, or "" when `word` names no topic.
std::string help_topic_text(std::string_view word);

// "topics (help <topic>): speed push ...\n": the line `help` without a word ends with.
std::string help_topic_list();

}  // namespace stride::console
