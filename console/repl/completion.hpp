#pragma once
// Tab completion for the REPL: commands, keys (representation:/module: names and their fields),
// providers, debug requests, switches and file paths. Pure over a RobotTarget and the file system.
#include <string>
#include <vector>

#include "console/target/robot_target.hpp"

namespace stride::console {

// Candidates (full words) for `word`, the word under the cursor, after the words `before` it;
// `robots` are the names `robot` takes (local robots and connections).
std::vector<std::string> complete(const std::vector<std::string>& before, const std::string& word,
                                  RobotTarget& target, const std::vector<std::string>& robots = {});

// Key completion alone: "representation:Jo" -> "representation:JointRequest", fields after '.'.
std::vector<std::string> complete_key(const std::string& word, RobotTarget& target);

// Paths starting with `word`; directories end with '/'.
std::vector<std::string> complete_path(const std::string& word);

}  // namespace stride::console
