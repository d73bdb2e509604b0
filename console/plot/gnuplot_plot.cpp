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

namespace stride::plot {

namespace {
// gnuplot single-quoted string: a quote is doubled.
std::string quoted(std::string_view s) {
  std::string r = "'";
  for (char c : s) r += c == '\'' ? std::string("''") : std::string(1, c);
  return r + "'";
}

std::vector<std::string> read_header(const std::string& csv_path) {
  std::ifstream in(csv_path);
  if (!in) throw Error("plot: cannot read CSV '" + csv_path + "'");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> cols;
  std::stringstream ss(line);
  for (std::string c; std::getline(ss, c, ',');) cols.push_back(c);
  return cols;
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
    FILE* pipe = popen("gnuplot -e 'set terminal' 2>&1", "r");
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

std::string gnuplot_script(const PlotSpec& spec, const std::vector<std::string>& csv_columns,
                           std::string_view terminal) {
  if (spec.series.empty()) throw Error("plot: no series to draw in " + spec.png_path);
  std::ostringstream s;
  s << "set terminal " << terminal << " size " << spec.width << "," << spec.height
    << (terminal == "pngcairo" ? " enhanced font 'Sans,10'" : "") << "\n";
  s << "set output " << quoted(spec.png_path) << "\n";
  s << "set datafile separator ','\nset datafile missing 'NaN'\nset key outside right\n";
  s << "set grid\nset title " << quoted(spec.title) << " noenhanced\n";
  s << "set xlabel " << quoted(spec.x_label) << "\nset ylabel " << quoted(spec.y_label) << "\n";
  if (!spec.x_range.empty()) s << "set xrange " << spec.x_range << "\n";
  if (!spec.y_range.empty()) s << "set yrange " << spec.y_range << "\n";
  s << "plot ";
  for (std::size_t i = 0; i < spec.series.size(); ++i) {
    const Series& ser = spec.series[i];
    const std::string& xc = ser.x_column.empty() ? spec.x_column : ser.x_column;
    s << (i ? ", \\\n     " : "") << quoted(spec.csv_path) << " skip 1 using "
      << column_index(csv_columns, xc, spec.csv_path) << ":"
      << column_index(csv_columns, ser.column, spec.csv_path) << " with " << spec.style
      << " lw 2 title " << quoted(ser.label.empty() ? ser.column : ser.label) << " noenhanced";
  }
  s << "\n";
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
  const console::ChildResult r = console::run_child({"gnuplot"}, to_stdout);
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
  const std::string script = gnuplot_script(spec, read_header(spec.csv_path), terminal);
  std::string gp_path = spec.png_path;
  if (gp_path.size() > 4 && gp_path.substr(gp_path.size() - 4) == ".png")
    gp_path.resize(gp_path.size() - 4);
  gp_path += ".gp";
  run_gnuplot(gp_path, script, spec.png_path);
}

}  // namespace stride::plot
