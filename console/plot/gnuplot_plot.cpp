#include "console/plot/gnuplot_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "console/system/child_process.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"
#include "robot/core/quote.hpp"

namespace stride::plot {

namespace {
// gnuplot single-quoted string: a quote is doubled.
std::string quoted(std::string_view s) {
  std::string r = "'";
  for (char c : s) r += c == '\'' ? std::string("''") : std::string(1, c);
  return r + "'";
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cols;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cols.push_back(c);
  return cols;
}

CsvCells read_cells(const std::string& csv_path) {
  std::ifstream in(csv_path);
  if (!in) throw Error("plot: cannot read CSV '" + csv_path + "'");
  CsvCells cells;
  for (std::string line; std::getline(in, line);) cells.push_back(split_csv_line(line));
  if (cells.empty()) throw Error("plot: CSV '" + csv_path + "' is empty");
  return cells;
}

int column_index(const std::vector<std::string>& cols, const std::string& name,
                 const std::string& csv_path) {
  const auto it = std::find(cols.begin(), cols.end(), name);
  if (it == cols.end()) throw Error("plot: column '" + name + "' not in " + csv_path);
  return static_cast<int>(it - cols.begin()) + 1;  // gnuplot counts from 1
}
}  // namespace

void Table::add_row(std::vector<double> row) {
  if (row.size() != columns.size())
    throw Error("plot table: row has " + std::to_string(row.size()) + " values, expected " +
                std::to_string(columns.size()));
  rows.push_back(std::move(row));
}

void write_csv(const std::string& path, const Table& table) {
  std::string out;
  for (std::size_t i = 0; i < table.columns.size(); ++i) out += (i ? "," : "") + table.columns[i];
  out += "\n";
  char buf[32];
  for (const auto& row : table.rows) {
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (std::isfinite(row[i]))
        std::snprintf(buf, sizeof buf, "%.10g", row[i]);
      else
        std::snprintf(buf, sizeof buf, "NaN");
      if (i) out += ',';
      out += buf;
    }
    out += "\n";
  }
  write_file(path, out);
}

std::string png_terminal() {
  // Asked once per process: the installed gnuplot does not change while we run.
  static const std::string terminal = [] {
    // Never the console's stdin: gnuplot's pager would eat the lines typed meanwhile.
    FILE* pipe = popen("gnuplot -e 'set terminal' </dev/null 2>&1", "r");
    if (!pipe) return std::string();
    std::string text;
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe)) text += buf;
    pclose(pipe);
    if (text.find("pngcairo") != std::string::npos) return std::string("pngcairo");
    if (text.find(" png ") != std::string::npos) return std::string("png");
    return std::string();
  }();
  return terminal;
}

bool labels_unit(std::string_view label) {
  while (!label.empty() && label.back() == ' ') label.remove_suffix(1);
  const std::size_t open = label.rfind('[');
  return label.size() >= 3 && label.back() == ']' && open != std::string_view::npos &&
         open + 2 < label.size();
}

namespace {

// The panels a spec draws: its own, or one made of its single-axis fields.
std::vector<Panel> panels_of(const PlotSpec& spec) {
  if (!spec.panels.empty()) return spec.panels;
  return {Panel{spec.y_label, spec.series, spec.references, spec.y_range}};
}

void check_units(const PlotSpec& spec, const std::vector<Panel>& panels) {
  if (!labels_unit(spec.x_label))
    throw Error("plot " + spec.png_path + ": x axis " + quote(spec.x_label) +
                " names no unit (expected e.g. 't [s]')");
  for (const Panel& p : panels)
    if (!labels_unit(p.y_label))
      throw Error("plot " + spec.png_path + ": y axis " + quote(p.y_label) +
                  " names no unit (expected e.g. 'angle [rad]'; one unit per panel)");
}

// gnuplot's line colour of series i (its default sequence), so a reference can match its curve.
std::string colour_of(int series) {
  return series >= 0 ? "lc " + std::to_string(series + 1) : "lc rgb '#555555'";
}

// Series `name`'s (x, y) columns as a gnuplot datablock; rows narrower than the header are left
// out (a cut last line).
void write_datablock(std::ostringstream& s, const std::string& name, const CsvCells& cells,
                     int x_column, int y_column) {
  s << name << " << EOD\n";
  const std::size_t need = static_cast<std::size_t>(std::max(x_column, y_column));
  for (std::size_t r = 1; r < cells.size(); ++r)
    if (cells[r].size() >= need)
      s << cells[r][static_cast<std::size_t>(x_column - 1)] << ','
        << cells[r][static_cast<std::size_t>(y_column - 1)] << '\n';
  s << "EOD\n";
}

void write_panel(std::ostringstream& s, const PlotSpec& spec, const Panel& panel,
                 const std::vector<std::string>& csv_columns, const CsvCells* cells,
                 int panel_index) {
  if (panel.series.empty()) throw Error("plot: no series to draw in " + spec.png_path);
  std::vector<std::string> sources;  // per series: what its plot clause reads, and its columns
  for (std::size_t i = 0; i < panel.series.size(); ++i) {
    const Series& ser = panel.series[i];
    const int x = column_index(csv_columns, ser.x_column.empty() ? spec.x_column : ser.x_column,
                               spec.csv_path);
    const int y = column_index(csv_columns, ser.column, spec.csv_path);
    if (!cells) {
      sources.push_back(quoted(spec.csv_path) + " skip 1 using " + std::to_string(x) + ":" +
                        std::to_string(y));
      continue;
    }
    const std::string name = "$p" + std::to_string(panel_index) + "s" + std::to_string(i);
    write_datablock(s, name, *cells, x, y);
    sources.push_back(name + " using 1:2");
  }
  s << "set ylabel " << quoted(panel.y_label) << "\n";
  s << (panel.y_range.empty() ? "set autoscale y" : "set yrange " + panel.y_range) << "\n";
  s << "unset arrow\nunset label\n";
  int vertical = 0;
  for (const Reference& r : panel.references) {
    if (!r.vertical) continue;
    s << "set arrow from " << r.value << ", graph 0 to " << r.value
      << ", graph 1 nohead dt 2 lw 1.5 " << colour_of(r.series) << "\n";
    s << "set label " << ++vertical << " " << quoted(r.label) << " at " << r.value
      << ", graph 0.97 left offset 0.5,0 noenhanced\n";
  }
  s << "plot ";
  for (std::size_t i = 0; i < panel.series.size(); ++i) {
    const Series& ser = panel.series[i];
    s << (i ? ", \\\n     " : "") << sources[i] << " with " << spec.style << " lw 2 "
      << colour_of(static_cast<int>(i)) << " title "
      << quoted(ser.label.empty() ? ser.column : ser.label) << " noenhanced";
  }
  for (const Reference& r : panel.references)
    if (!r.vertical)
      s << ", \\\n     " << r.value << " with lines dt 2 lw 1.5 " << colour_of(r.series)
        << " title " << quoted(r.label) << " noenhanced";
  s << "\n";
}

}  // namespace

std::string gnuplot_script(const PlotSpec& spec, const std::vector<std::string>& csv_columns,
                           std::string_view terminal, const CsvCells* cells) {
  const std::vector<Panel> panels = panels_of(spec);
  check_units(spec, panels);
  const int n = static_cast<int>(panels.size());
  const int height = n == 1 ? spec.height : std::max(spec.height, (spec.height * 6 / 10) * n);
  std::ostringstream s;
  s << "set terminal " << terminal << " size " << spec.width << "," << height
    << (terminal == "pngcairo" ? " enhanced font 'Sans,10'" : "") << "\n";
  s << "set output " << quoted(spec.png_path) << "\n";
  s << "set datafile separator ','\nset datafile missing 'NaN'\nset key " << spec.key << "\n";
  s << "set grid\nset xlabel " << quoted(spec.x_label) << "\n";
  if (!spec.x_range.empty()) s << "set xrange " << spec.x_range << "\n";
  if (n == 1)
    s << "set title " << quoted(spec.title) << " noenhanced\n";
  else  // panels share the x axis; the left margin lines their y axes up
    s << "set multiplot layout " << n << ",1 title " << quoted(spec.title)
      << " noenhanced\nset lmargin 12\n";
  for (std::size_t i = 0; i < panels.size(); ++i)
    write_panel(s, spec, panels[i], csv_columns, cells, static_cast<int>(i));
  if (n > 1) s << "unset multiplot\n";
  return s.str();
}

void run_gnuplot(const std::string& gp_path, const std::string& script,
                 const std::string& png_path) {
  write_file(gp_path, script);  // kept beside the picture, to be tweaked and rerun by hand
  // gnuplot draws to its standard output, so the PNG reaches disk through the checked writer.
  std::string to_stdout;
  std::istringstream lines(script);
  for (std::string line; std::getline(lines, line);)
    to_stdout += (line.starts_with("set output ") ? std::string("set output") : line) + "\n";
  // Handed over as a file: gnuplot reads a script from a pipe one byte per read() (7.5 million
  // calls for a 400-curve plot with its data), from a file in blocks.
  const std::string run_path = gp_path + ".run";
  write_file(run_path, to_stdout);
  console::ChildResult r;
  try {
    r = console::run_child({"gnuplot", run_path}, "");
  } catch (...) {
    std::remove(run_path.c_str());
    throw;
  }
  std::remove(run_path.c_str());
  if (r.exit_status != 0 || !r.out.starts_with("\x89PNG")) {
    std::string why = r.err.empty() ? "no PNG produced" : r.err;
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw Error("plot: gnuplot failed on " + gp_path + ": " + why);
  }
  write_file(png_path, r.out);
}

void render_png(const PlotSpec& spec) {
  const std::string terminal = png_terminal();
  if (terminal.empty())
    throw Error("plot: gnuplot with a png terminal not found (install gnuplot-nox)");
  const CsvCells cells = read_cells(spec.csv_path);
  const std::string script = gnuplot_script(spec, cells.front(), terminal, &cells);
  std::string gp_path = spec.png_path;
  if (gp_path.size() > 4 && gp_path.substr(gp_path.size() - 4) == ".png")
    gp_path.resize(gp_path.size() - 4);
  gp_path += ".gp";
  run_gnuplot(gp_path, script, spec.png_path);
}

}  // namespace stride::plot
