#pragma once
// Where a study's figures go, the same for every experiment: one folder per figure family,
//   <out>/figures/<family>/<name>.png  (beside its .gp, and its .csv when it has one)
// so that cases of one family sit side by side and <out>/index.html shows them by family.
#include <string>

namespace stride::plot {

// Creates `dir` and its parents; throws stride::Error naming it when it cannot be made.
void make_directory(const std::string& dir);

// Creates and returns <out_dir>/figures/<family>.
std::string figure_dir(const std::string& out_dir, const std::string& family);

// figure_dir(out_dir, family) + "/" + name: a figure's path without its extension.
std::string figure_stem(const std::string& out_dir, const std::string& family,
                        const std::string& name);

}  // namespace stride::plot
