#include "console/experiments/push_figures.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "console/plot/figure_folder.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "console/plot/run_figures.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/output_file.hpp"

namespace stride::experiments {
namespace {

namespace fs = std::filesystem;

// The impulses drawn in a phase portrait: recovered and fallen pushes both ways, few enough to
// tell the curves apart.
constexpr double kPortraitImpulses[] = {-3, -2, -1, 1, 2, 3};

// One traced run: its (x, capture point) pairs.
std::vector<std::pair<double, double>> trace_points(const std::string& path) {
  std::vector<std::pair<double, double>> points;
  for (const auto& row : read_trace(path, {"x", "capture_point"}))
    points.emplace_back(row[0], row[1]);
  return points;
}

// The Ch. 7 boundaries of one traced run in the capture-point form: each strategy's interval
// [lo, hi] of x + xdot / omega, dashed, one colour per strategy (after the six curves').
std::vector<plot::Reference> boundaries(const RunsCsv& runs, const std::vector<std::string>& row) {
  std::vector<plot::Reference> refs;
  int colour = 6;
  for (const auto& [key, label] :
       {std::pair{"ankle", "ankle (Eq. 7.13)"}, std::pair{"hip", "hip (Eq. 7.30)"},
        std::pair{"combined", "combined (Eq. 7.37)"}}) {
    for (const char* end : {"lo", "hi"})
      refs.push_back({runs.number(row, std::string(key) + "_" + end),
                      std::string(label) + (end[0] == 'l' ? " back" : " front"), false,
                      colour < 8 ? colour : -1});
    ++colour;
  }
  return refs;
}

std::string outcome(const RunsCsv& runs, const std::vector<std::string>& row) {
  if (runs.number(row, "recovered") != 0) return "recovered";
  return runs.number(row, "fell") != 0 ? "fell" : "feet moved";
}

}  // namespace

namespace {

// One control's portrait: the runs' curves side by side in one CSV (x_k, cp_k), NaN-padded.
void portrait(const std::string& out_dir, const std::string& control,
              const std::vector<std::pair<std::string, std::string>>& traces,
              const std::vector<plot::Reference>& refs, bool png) {
  plot::Table table;
  plot::PlotSpec spec;
  std::vector<std::vector<std::pair<double, double>>> curves;
  std::size_t longest = 0;
  for (std::size_t k = 0; k < traces.size(); ++k) {
    const std::string id = std::to_string(k + 1);
    table.columns.push_back("x_" + id);
    table.columns.push_back("cp_" + id);
    spec.series.push_back({"cp_" + id, traces[k].first, "x_" + id});
    curves.push_back(trace_points(traces[k].second));
    longest = std::max(longest, curves.back().size());
  }
  for (std::size_t i = 0; i < longest; ++i) {
    std::vector<double> row;
    for (const auto& c : curves) {
      row.push_back(i < c.size() ? c[i].first : NAN);
      row.push_back(i < c.size() ? c[i].second : NAN);
    }
    table.add_row(std::move(row));
  }
  const std::string stem = plot::figure_stem(out_dir, "phase_portraits", control);
  plot::write_csv(stem + ".csv", table);
  if (!png) return;
  spec.csv_path = stem + ".csv";
  spec.png_path = stem + ".png";
  spec.x_column = table.columns.front();
  spec.title = "Standing NAO, " + control +
               ": CoM after a 0.05 s torso push against the Ch. 7 boundaries (seed 1)";
  spec.x_label = "CoM x [m]";
  spec.y_label = "capture point x + xdot/omega [m]";
  spec.x_range = "[-0.06:0.10]";
  spec.y_range = "[-0.15:0.2]";
  spec.references = refs;
  plot::render_png(spec);
}

}  // namespace

void write_phase_portraits(const std::string& out_dir, bool png) {
  const RunsCsv runs = read_runs_csv(out_dir);
  // per control: its traced runs (label, trace file) and the boundaries
  std::map<std::string, std::vector<std::pair<std::string, std::string>>> traces;
  std::map<std::string, std::vector<plot::Reference>> refs;
  for (const auto& row : runs.rows) {
    const fs::path trace = trace_path(out_dir, runs, row);
    const double impulse = runs.number(row, "impulse");
    if (!fs::exists(trace) || std::find(std::begin(kPortraitImpulses), std::end(kPortraitImpulses),
                                        impulse) == std::end(kPortraitImpulses))
      continue;
    const std::string& control = row[runs.column("control")];
    traces[control].emplace_back(row[runs.column("impulse")] + " N s, " + outcome(runs, row),
                                 trace.string());
    if (!refs.count(control)) refs[control] = boundaries(runs, row);
  }
  const bool draw = png && !plot::png_terminal().empty();
  for (const auto& [control, list] : traces)
    portrait(out_dir, control, list, refs.at(control), draw);
}

std::vector<MapCell> push_map_cells(const RunsCsv& runs) {
  std::vector<MapCell> cells;
  for (const auto& row : runs.rows) {
    MapCell key{row[runs.column("control")], row[runs.column("dir")], runs.number(row, "N"),
                runs.number(row, "phase")};
    if (key.direction == "none") continue;
    auto it = std::find_if(cells.begin(), cells.end(), [&](const MapCell& c) {
      return c.control == key.control && c.direction == key.direction && c.push == key.push &&
             c.phase == key.phase;
    });
    if (it == cells.end()) it = cells.insert(cells.end(), key);
    ++it->walks;
    it->lost += runs.number(row, "lost") != 0 ? 1 : 0;
  }
  return cells;
}

namespace {

// The smallest gap between the distinct values (1 for a single value): the width of a map cell.
double spacing(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  double gap = v.size() > 1 ? v[1] - v[0] : 1.0;
  for (std::size_t i = 2; i < v.size(); ++i) gap = std::min(gap, v[i] - v[i - 1]);
  return gap;
}

// One map per control side by side: x the gait phase, y the push, each cell a box coloured by
// the share of walks lost and labelled lost/walks (boxes, not an image: a cell run at one phase
// only leaves the grid irregular). The data go into the script, so the .gp redraws alone.
std::string map_script(const std::vector<MapCell>& cells, const std::string& direction,
                       const std::string& png, const std::vector<std::string>& controls) {
  std::vector<double> phases, pushes;
  for (const MapCell& c : cells) phases.push_back(c.phase), pushes.push_back(c.push);
  const double hx = spacing(phases) / 2, hy = spacing(pushes) / 2;
  std::ostringstream s;
  s << "set terminal " << plot::png_terminal() << " size 1200,520\n";
  s << "set output '" << png << "'\n";
  s << "set multiplot layout 1," << controls.size() << " title 'Walking NAO (medium, 3 mm floor) "
    << "pushed " << direction << " on the torso for 0.1 s: walks lost of the seeds' noenhanced\n";
  s << "set xlabel 'push start [fraction of the stride after 6 s]'\n";
  s << "set ylabel 'push [N for 0.1 s]'\nset cblabel 'walks lost [fraction of the seeds]'\n";
  s << "set cbrange [0:1]\nset palette defined (0 'white', 0.5 'orange', 1 'red')\n";
  s << "set xrange [" << *std::min_element(phases.begin(), phases.end()) - hx << ":"
    << *std::max_element(phases.begin(), phases.end()) + hx << "]\n";
  s << "set yrange [" << *std::min_element(pushes.begin(), pushes.end()) - hy << ":"
    << *std::max_element(pushes.begin(), pushes.end()) + hy << "]\n";
  s << "set xtics " << 2 * hx << "\nset ytics " << 2 * hy << "\n";
  for (std::size_t k = 0; k < controls.size(); ++k) {
    s << "$map" << k << " << EOD\n";
    for (const MapCell& c : cells)
      if (c.control == controls[k] && c.direction == direction)
        s << c.phase << " " << c.push << " " << static_cast<double>(c.lost) / c.walks << " "
          << c.lost << " " << c.walks << "\n";
    s << "EOD\n";
  }
  for (std::size_t k = 0; k < controls.size(); ++k) {
    s << "set title '" << controls[k] << "' noenhanced\n";
    s << "plot $map" << k << " using 1:2:($1-" << hx << "):($1+" << hx << "):($2-" << hy << "):($2+"
      << hy << "):3 with boxxyerror fs solid 1.0 border lc rgb 'gray' fc palette notitle, $map" << k
      << " using 1:2:(sprintf('%d/%d', $4, $5)) with labels notitle\n";
  }
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace

void write_push_map(const std::string& out_dir, bool png) {
  const std::vector<MapCell> cells = push_map_cells(read_runs_csv(out_dir));
  std::ostringstream csv;
  csv << "control,dir,N,phase,walks,lost\n";
  std::vector<std::string> directions, controls;
  for (const MapCell& c : cells) {
    csv << c.control << "," << c.direction << "," << c.push << "," << c.phase << "," << c.walks
        << "," << c.lost << "\n";
    if (std::find(directions.begin(), directions.end(), c.direction) == directions.end())
      directions.push_back(c.direction);
    if (std::find(controls.begin(), controls.end(), c.control) == controls.end())
      controls.push_back(c.control);
  }
  write_file((fs::path(out_dir) / "push_map.csv").string(), csv.str());
  if (!png || plot::png_terminal().empty()) return;
  for (const std::string& d : directions) {
    const std::string stem = plot::figure_stem(out_dir, "push_map", d);
    plot::run_gnuplot(stem + ".gp", map_script(cells, d, stem + ".png", controls), stem + ".png");
  }
}

}  // namespace stride::experiments
