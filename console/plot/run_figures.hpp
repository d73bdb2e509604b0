#pragma once
// Several runs of the same quantities (e.g. one simulation per initial state) written as one long
// CSV, and as figures: one wide CSV + PNG per figure, one curve per run (and per quantity).
//
//   plot::RunSet set{{"t", "x", "v"}, {{"case A", rows_a}, {"case B", rows_b}}};
//   plot::write_long_csv(set, "all.csv");                     // case,t,x,v
//   plot::write_figure(set, {.stem = "com", .title = "CoM", .x_label = "t [s]",
//                            .y_label = "x [m]", .quantities = {"x"}}, "plots");
#include <string>
#include <vector>

#include "console/plot/gnuplot_plot.hpp"

namespace stride::plot {

struct Run {
  std::string name;                       // legend label
  std::vector<std::vector<double>> rows;  // one value per RunSet column; column 0 is time
};

struct RunSet {
  std::vector<std::string> columns;
  std::vector<Run> runs;
};

// A straight line y = slope x + intercept drawn across the phase plot (e.g. a boundary).
struct Line {
  std::string name;
  double slope = 0.0;
  double intercept = 0.0;
};

// One axis of a time plot with several units: its quantities share the unit in y_label.
struct FigurePanel {
  std::string y_label;                  // "x [m]"
  std::vector<std::string> quantities;  // columns drawn against column 0
  std::vector<Reference> references;    // values they are compared with (thesis, limits)
};

struct Figure {
  std::string stem;  // file names <dir>/<stem>.csv, .png, .gp
  std::string title, x_label, y_label;
  std::vector<std::string> quantities;  // time plot: these columns against column 0
  std::string phase_x, phase_y;         // if set: phase plot of phase_y against phase_x
  std::vector<Line> lines;              // phase plots only
  std::string x_range, y_range;         // gnuplot ranges such as "[-1:1]"; empty = automatic
  std::vector<Reference> references;    // of the single axis (time or phase plot)
  std::vector<FigurePanel> panels;      // if set: a time plot of stacked axes, one per unit
};

// Columns "case" (1-based run index) followed by the RunSet columns.
void write_long_csv(const RunSet& set, const std::string& path);

// Writes <dir>/<stem>.csv (NaN-padded wide table) and renders <dir>/<stem>.png. Throws
// stride::Error for an unknown column or a failed write/render.
void write_figure(const RunSet& set, const Figure& figure, const std::string& dir);

}  // namespace stride::plot
