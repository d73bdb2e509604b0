#pragma once
// The overview of a study's output: <out>/index.html shows every PNG below <out> as a thumbnail
// that links to the picture, one section per folder (a figure family), so 36 figures are one page
// to look through instead of a flat folder.
#include <iosfwd>
#include <string>
#include <vector>

namespace stride::experiments {

// One section of the index: a folder relative to the output ("." for the top) and its PNGs.
struct FigureFamily {
  std::string folder;
  std::vector<std::string> pictures;  // file names, sorted
};

// The PNGs below `out_dir` by folder, the top folder first, then folders in name order.
std::vector<FigureFamily> figure_families(const std::string& out_dir);

// Writes <out_dir>/index.html over figure_families(); returns its path, or "" when there is no
// PNG to show. Throws stride::Error when the page cannot be written.
std::string write_figure_index(const std::string& out_dir, const std::string& title);

// write_figure_index for `stride experiment <name>`, and a line "figures: <path> (N figures)"
// on `out` naming the page.
void print_figure_index(const std::string& out_dir, const std::string& experiment,
                        std::ostream& out);

}  // namespace stride::experiments
