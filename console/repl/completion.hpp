#pragma once
// Tab completion for the REPL: commands, keys (representation:/module: names and their fields),
// providers, debug requests, switches and file paths. Pure over a Target and the file system.
#include <string>
#include <vector>

#include "console/target/target.hpp"

namespace stride::console {

// Candidates (full words) for `word`, the word under the cursor, after the words `before` it.
std::vector<std::string> complete(const std::vector<std::string>& before, const std::string& word,
                                  Target& target);

// Key completion alone: "representation:Jo" -> "representation:JointRequest", fields after '.'.
std::vector<std::string> complete_key(const std::string& word, Target& target);

// Paths starting with `word`; directories end with '/'.
std::vector<std::string> complete_path(const std::string& word);

}  // namespace stride::console
