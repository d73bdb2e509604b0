#pragma once
// What every `stride experiment <name>` takes: where the sweep files and scenes are, where
// results go, how many noise seeds to repeat with, and how many walks run at once.
#include <filesystem>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "console/plot/gnuplot_plot.hpp"
#include "console/sweep/sweep_spec.hpp"

namespace stride::experiments {

struct ExperimentOptions {
  std::string sweeps_dir = "scenes/experiments";  // <name>.sweep.xml
  std::string scenes_dir;                         // empty: the sweep file's own scenes
  std::string out_dir;                            // empty: print the tables only
  int seeds = 0;                                  // 0: the experiment's own default
  bool plots = true;                              // PNGs next to the CSVs (needs gnuplot)
  int jobs = 0;                                   // walks at once; 0: every hardware thread
  bool resume = false, quiet = false;
  // --set Module.field=value, in order: {module, "field=value"} applied to every walk.
  std::vector<std::pair<std::string, std::string>> parameters;
  // --physics engine=mujoco,solver=exact: scene:physics@ settings over every walk's <physics>.
  std::vector<sweep::Setting> physics;
  // --cases a,b: the posture cases to run, each a scene name or a strategy (none|hip|ankle);
  // empty: all nine.
  std::vector<std::string> cases;
  // --only column=a,b: only the runs with these levels (seed-major studies: --only seed=1,2).
  std::vector<std::pair<std::string, std::vector<std::string>>> only;
  std::string command;  // the command line, for a sweep's manifest
  // --through-lola / --lola-packets: where robot 0's controller runs (sweep_spec.hpp).
  sweep::RobotLink link = sweep::RobotLink::InProcess;
};

// The scene <name>.xml the kalman study walks: in scenes_dir if given, else in sweeps_dir.
std::string scene_path(const ExperimentOptions& o, const std::string& name);

// Creates out_dir if results are to be written; returns false when out_dir is empty.
bool prepare_out_dir(const ExperimentOptions& o);

// Creates <out>/<folder> (a figure family's folder) when results are written; throws
// stride::Error naming it when it cannot be made.
void make_figure_dir(const ExperimentOptions& o, const std::string& folder);

// Writes <out>/<stem>.csv and, if plots are on, <out>/<stem>.png with y columns against x_column.
void write_plot(const ExperimentOptions& o, const plot::Table& table, const std::string& stem,
                const std::string& title, const std::string& x_column,
                const std::vector<plot::Series>& series, const std::string& x_label,
                const std::string& y_label, const std::string& style = "lines");

// The same for a figure of several panels or with reference values: `spec` gives everything
// but the file names.
void write_plot(const ExperimentOptions& o, const plot::Table& table, const std::string& stem,
                plot::PlotSpec spec);

// Fixed-width table printing: a header, then rows of already formatted cells.
void print_table(std::ostream& out, const std::vector<std::string>& header,
                 const std::vector<std::vector<std::string>>& rows);
std::string fixed(double v, int decimals);

}  // namespace stride::experiments
