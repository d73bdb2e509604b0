#pragma once
// What every `stride experiment <name>` takes: where the scenes are, where results go, how many
// noise seeds to repeat with, and where its table is printed.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "console/plot/gnuplot_plot.hpp"

namespace stride::experiments {

struct ExperimentOptions {
  std::string scenes_dir = "scenes/experiments";
  std::string out_dir;  // empty: print the table only
  int seeds = 0;        // 0: the experiment's own default
  bool plots = true;    // PNGs next to the CSVs (needs gnuplot)
  int jobs = 1;         // walks run at once (worker processes); results do not depend on it
  // --set Module.field=value, in order: {module, "field=value"} applied to every walk.
  std::vector<std::pair<std::string, std::string>> parameters;
  // --cases a,b: the posture cases to run, each a scene name or a strategy (none|hip|ankle);
  // empty: all nine.
  std::vector<std::string> cases;
};

// scenes_dir/<name>.xml; throws stride::Error naming the path when it does not exist.
std::string scene_path(const ExperimentOptions& o, const std::string& name);

// Creates out_dir if results are to be written; returns false when out_dir is empty.
bool prepare_out_dir(const ExperimentOptions& o);

// Writes <out>/<stem>.csv and, if plots are on, <out>/<stem>.png with y columns against x_column.
void write_plot(const ExperimentOptions& o, const plot::Table& table, const std::string& stem,
                const std::string& title, const std::string& x_column,
                const std::vector<plot::Series>& series, const std::string& x_label,
                const std::string& y_label, const std::string& style = "lines");

// Fixed-width table printing: a header, then rows of already formatted cells.
void print_table(std::ostream& out, const std::vector<std::string>& header,
                 const std::vector<std::vector<std::string>>& rows);
std::string fixed(double v, int decimals);

}  // namespace stride::experiments
