#include "console/experiments/posture_figures.hpp"

#include <filesystem>

#include "console/plot/gnuplot_plot.hpp"

namespace stride::experiments {
namespace {

namespace fs = std::filesystem;

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

void figure(const std::string& csv, const std::string& stem, const std::string& title, bool ankle) {
  const std::string joint = ankle ? "ankle" : "hip";
  std::vector<plot::Series> angles;
  for (const char* side : {"l"})
    for (const char* axis : {"pitch", "roll"})
      for (const char* kind : {"ref", "mod"})
        angles.push_back({joint + "_" + axis + "_" + kind + "_" + side, "", ""});
  panel(csv, stem + "_a_" + joint + "_angles.png",
        title + ": (a) reference and modified " + joint + " angles (left leg)", "t", angles,
        "t [s]", "angle [rad]");
  panel(csv, stem + "_b_torso.png", title + ": (b) torso inclination", "t",
        {{"true_pitch", "pitch (ground truth)", ""},
         {"true_roll", "roll (ground truth)", ""},
         {"est_pitch", "pitch (Kalman)", ""},
         {"est_roll", "roll (Kalman)", ""}},
        "t [s]", "[rad]");
  panel(csv, stem + "_c_waist_velocity.png", title + ": (c) waist velocity", "t",
        {{"waist_v_ref", "reference", ""}, {"waist_v", "actual (torso, ground truth)", ""}},
        "t [s]", "v_x [m/s]");
  panel(
      csv, stem + "_d_zmp.png", title + ": (d) ZMP (CoP from the FSRs) in the world frame", "cop_x",
      {{"cop_y", "measured (FSR CoP)", "cop_x"}, {"zmp_ref_y", "planned (Eq. 3.16)", "zmp_ref_x"}},
      "x [m]", "y [m]");
}

}  // namespace

void write_posture_figures(const std::string& out_dir, const sweep::SweepResult& result, bool png) {
  if (!png || plot::png_terminal().empty()) return;
  // Row cells: run, scene, case, figure, thesis..., seed, status, ...
  for (const auto& row : result.rows) {
    const fs::path trace = fs::path(out_dir) / "traces" / ("run-" + row[0] + ".csv");
    std::error_code ec;
    if (!fs::exists(trace, ec)) continue;
    const std::string& name = row[2];
    figure(trace.string(), (fs::path(out_dir) / ("posture_" + name)).string(), name + " " + row[3],
           name.rfind("ankle", 0) == 0);
  }
}

}  // namespace stride::experiments
