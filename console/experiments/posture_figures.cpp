#include "console/experiments/posture_figures.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "console/plot/figure_folder.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "console/sweep/csv_line.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

namespace fs = std::filesystem;

// A trace's columns by name; a cell that is no number (a "nan" while airborne) is NaN.
std::map<std::string, std::vector<double>> read_columns(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot be read");
  std::string line;
  std::vector<std::string> header;
  if (std::getline(in, line)) header = sweep::parse_csv_line(line).value_or(header);
  if (header.empty()) throw Error(path + ": empty (expected a header line)");
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line)) {
    const auto cells = sweep::parse_csv_line(line);
    if (!cells || cells->size() != header.size()) continue;  // a cut last line
    for (std::size_t i = 0; i < header.size(); ++i) {
      char* end = nullptr;
      const double v = std::strtod((*cells)[i].c_str(), &end);
      columns[header[i]].push_back(end && *end == '\0' && !(*cells)[i].empty() ? v : NAN);
    }
  }
  return columns;
}

bool has(const std::map<std::string, std::vector<double>>& c, const std::vector<std::string>& n) {
  for (const std::string& name : n)
    if (!c.count(name)) return false;
  return true;
}

void panel(const std::string& csv, const std::string& png, const std::string& title,
           const std::string& x, std::vector<plot::Series> series, const std::string& x_label,
           const std::string& y_label, const std::string& style = "lines") {
  plot::PlotSpec spec{.csv_path = csv,
                      .x_column = x,
                      .series = std::move(series),
                      .title = title,
                      .x_label = x_label,
                      .y_label = y_label,
                      .png_path = png};
  spec.style = style;
  plot::render_png(spec);
}

std::string picture(const std::string& out_dir, const std::string& family, const std::string& c) {
  return plot::figure_stem(out_dir, family, c) + ".png";
}

// (e): the measured CoP from the true feet midpoint, turned into the torso's heading, against the
// plan's ZMP from the walking line (its feet stand +-d_0 about it, so that is its feet midpoint).
void feet_frame_figure(const std::string& out_dir, const std::string& case_name,
                       const std::string& title,
                       const std::map<std::string, std::vector<double>>& c) {
  const auto &t = c.at("t"), &cop_x = c.at("cop_x"), &cop_y = c.at("cop_y");
  const auto &feet_x = c.at("feet_x"), &feet_y = c.at("feet_y"), &yaw = c.at("torso_yaw");
  const auto& zmp_y = c.at("zmp_ref_y");
  if (t.empty()) return;
  const double line_y = feet_y.front();  // standing still before the walk: the plan's origin
  plot::Table table{{"t", "cop_lateral", "zmp_ref_lateral"}};
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double dx = cop_x[i] - feet_x[i], dy = cop_y[i] - feet_y[i];
    table.add_row({t[i], -std::sin(yaw[i]) * dx + std::cos(yaw[i]) * dy, zmp_y[i] - line_y});
  }
  const std::string png = picture(out_dir, "zmp_feet_frame", case_name);
  const std::string csv = png.substr(0, png.size() - 4) + ".csv";
  plot::write_csv(csv, table);
  panel(csv, png, title + ": (e) lateral ZMP from the feet midpoint", "t",
        {{"cop_lateral", "measured FSR CoP - true feet midpoint", ""},
         {"zmp_ref_lateral", "planned ZMP (Eq. 3.16) - walking line", ""}},
        "t [s]", "lateral from the feet midpoint, heading frame [m]");
}

}  // namespace

const std::vector<std::string>& posture_figure_families() {
  static const std::vector<std::string> families = {
      "joint_angles", "torso_inclination", "waist_velocity", "zmp_world", "zmp_feet_frame"};
  return families;
}

void write_posture_case_figures(const std::string& out_dir, const std::string& trace_csv,
                                const std::string& case_name, const std::string& figure) {
  const auto columns = read_columns(trace_csv);
  const std::string title = case_name + " " + figure;
  const std::string joint = case_name.rfind("ankle", 0) == 0 ? "ankle" : "hip";
  std::vector<plot::Series> angles;
  for (const char* axis : {"pitch", "roll"})
    for (const char* kind : {"ref", "mod"})
      angles.push_back({joint + "_" + axis + "_" + kind + "_l", "", ""});
  panel(trace_csv, picture(out_dir, "joint_angles", case_name),
        title + ": (a) reference and modified " + joint + " angles (left leg)", "t", angles,
        "t [s]", "angle [rad]");
  // The estimates first and the ground truth last, so the true curves are drawn on top.
  panel(trace_csv, picture(out_dir, "torso_inclination", case_name),
        title + ": (b) torso inclination, ground truth on top", "t",
        {{"est_pitch", "pitch (Kalman)", ""},
         {"est_roll", "roll (Kalman)", ""},
         {"true_pitch", "pitch (ground truth)", ""},
         {"true_roll", "roll (ground truth)", ""}},
        "t [s]", "angle [rad]");
  panel(trace_csv, picture(out_dir, "waist_velocity", case_name), title + ": (c) waist velocity",
        "t", {{"waist_v_ref", "reference", ""}, {"waist_v", "actual (torso, ground truth)", ""}},
        "t [s]", "v_x [m/s]");
  std::vector<plot::Series> zmp = {{"cop_y", "measured (FSR CoP)", "cop_x"},
                                   {"zmp_ref_y", "planned (Eq. 3.16) from the start", "zmp_ref_x"}};
  if (has(columns, {"feet_x", "feet_y"}))
    zmp.push_back({"feet_y", "true feet midpoint (where the walk went)", "feet_x"});
  panel(trace_csv, picture(out_dir, "zmp_world", case_name),
        title + ": (d) ZMP in the world frame; the plan is laid straight from the start", "cop_x",
        zmp, "x, world frame [m]", "y, world frame [m]");
  if (has(columns, {"t", "cop_x", "cop_y", "feet_x", "feet_y", "torso_yaw", "zmp_ref_y"}))
    feet_frame_figure(out_dir, case_name, title, columns);
}

void write_posture_figures(const std::string& out_dir, const sweep::SweepResult& result, bool png) {
  if (!png || plot::png_terminal().empty()) return;
  // Row cells: run, scene, case, figure, thesis..., seed, status, ...
  for (const auto& row : result.rows) {
    const fs::path trace = fs::path(out_dir) / "traces" / ("run-" + row[0] + ".csv");
    std::error_code ec;
    if (!fs::exists(trace, ec)) continue;
    write_posture_case_figures(out_dir, trace.string(), row[2], row[3]);
  }
}

}  // namespace stride::experiments
