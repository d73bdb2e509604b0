#pragma once
// Write a numeric table as CSV and render columns of it to PNG with gnuplot (`gnuplot` binary,
// Debian gnuplot-nox). Reusable for any figure: one CSV, one x column, any number of y series.
//
//   plot::Table t{{"t", "x", "zmp"}};
//   t.add_row({0.0, 0.01, 0.0});
//   plot::write_csv("out/com.csv", t);
//   plot::PlotSpec spec{.csv_path = "out/com.csv", .x_column = "t",
//                       .series = {{"x", "CoM x"}, {"zmp", "ZMP"}},
//                       .title = "CoM", .x_label = "t [s]", .y_label = "[m]",
//                       .png_path = "out/com.png"};
//   plot::render_png(spec);  // also leaves out/com.gp, the script, for tweaking by hand
#include <string>
#include <string_view>
#include <vector>

namespace stride::plot {

// Named numeric columns; non-finite values are written as NaN and left out of plots.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  void add_row(std::vector<double> row);  // throws stride::Error if the width is wrong
};

// CSV with one header line; full double precision. Throws stride::Error naming the path.
void write_csv(const std::string& path, const Table& table);

// One curve: y column, legend label (column name if empty), and optionally its own x column
// (for phase-plane plots where each curve has its own x).
struct Series {
  std::string column;
  std::string label;
  std::string x_column;
};

// A value a curve is compared with (a true parameter, a thesis figure): a dashed line across the
// panel, horizontal at y = value or, if `vertical`, at x = value; in the colour of series
// `series` of its panel when that is >= 0, else grey.
struct Reference {
  double value = 0;
  std::string label;
  bool vertical = false;
  int series = -1;
};

// One y axis: curves of one unit. y_label names the quantity and its unit: "angle [rad]".
struct Panel {
  std::string y_label;
  std::vector<Series> series;
  std::vector<Reference> references;
  std::string y_range;
};

// One figure. Either `series` with `y_label` (and `references`, `y_range`) for one axis, or
// `panels`: stacked axes sharing x, one per unit, so that no axis mixes units. Every axis label
// must end in its unit in brackets ("t [s]", "ratio [-]"); render_png refuses one that does not.
struct PlotSpec {
  std::string csv_path;
  std::string x_column;
  std::vector<Series> series;
  std::string title;
  std::string x_label;
  std::string y_label;
  std::string png_path;
  int width = 900;
  int height = 600;             // of one panel; stacked panels take 0.6 of it each, at least
  std::string style = "lines";  // gnuplot style: lines, points, linespoints
  std::string x_range;          // gnuplot range such as "[-0.3:0.3]"; empty = automatic
  std::string y_range;
  std::vector<Reference> references;
  std::vector<Panel> panels;
  std::string key = "outside right";  // gnuplot legend placement, e.g. "outside below"
};

// True when `label` ends in a bracketed unit: "t [s]", "[rad]", "K_p [-]".
bool labels_unit(std::string_view label);

// The PNG terminal this machine's gnuplot offers ("pngcairo" preferred, else "png"); empty if
// gnuplot is not installed.
std::string png_terminal();

// The CSV's cells as text, header first (what render_png embeds in its script).
using CsvCells = std::vector<std::vector<std::string>>;

// The gnuplot script for spec, given the CSV header columns (exposed for tests and debugging).
// With `cells` (the whole CSV), each curve's (x, y) pairs go into the script as a datablock, so
// gnuplot reads each value once: reading the CSV once per curve costs curves x columns per row,
// quadratic in the number of keys a console `plot` records.
std::string gnuplot_script(const PlotSpec& spec, const std::vector<std::string>& csv_columns,
                           std::string_view terminal, const CsvCells* cells = nullptr);

// Reads the CSV, writes <png without .png>.gp (data included) and runs gnuplot on it. Throws
// stride::Error when gnuplot is missing, a column is unknown, gnuplot fails or a file cannot be
// written.
void render_png(const PlotSpec& spec);

// Any gnuplot script whose `set output '<png_path>'` line names the picture: saved as gp_path,
// run with gnuplot drawing to its standard output, and the PNG written with every write checked.
void run_gnuplot(const std::string& gp_path, const std::string& script,
                 const std::string& png_path);

}  // namespace stride::plot
