// `stride pattern`: the thesis' walking pattern (Ch. 3) sampled offline to CSV and plots.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "behaviours/walking/pattern/pattern_joints.hpp"
#include "behaviours/walking/pattern/pattern_parameter_list.hpp"
#include "behaviours/walking/pattern/pattern_plausibility.hpp"
#include "behaviours/walking/pattern/pattern_study.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/output/output_paths.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/output_file.hpp"
#include "robot/core/quote.hpp"

namespace stride::cli {

namespace {

using walking::PatternSample;

struct PatternOptions {
  walking::PatternParameters params;
  bool conventional = false;
  double dt = 0.01;  // control period of the thesis (Sec. 3.6: 100 Hz)
  std::string csv, plots;
};

constexpr const char* kUsage =
    "usage: stride pattern [--preset slow|medium|fast|fig3.14|fig3.16|table4.4-5|-10|-15|-20] "
    "[--set name=value ...] "
    "[--conventional] [--dt s] --csv out.csv [--plots dir]";

double parse_period(const std::string& text) {
  const double v = parse_number(text, "--dt");
  // The lower bound keeps a 15 s walk to 150 000 samples.
  if (!(v >= 1e-4 && v <= 1.0))
    throw UsageError("--dt: expected a period in [0.0001, 1] s, got " + quote(text));
  return v;
}

PatternOptions parse_options(Args args) {
  ArgumentReader a(args, "pattern");
  PatternOptions o;
  if (a.has("--preset")) o.params = walking::preset(a.text("--preset"));
  std::vector<std::pair<std::string, std::string>> sets;
  for (const std::string& kv : a.texts("--set")) {
    const std::size_t eq = kv.find('=');
    if (eq == std::string::npos) throw UsageError("--set: expected name=value, got " + quote(kv));
    sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  o.conventional = a.flag("--conventional");
  if (a.has("--dt")) o.dt = parse_period(a.text("--dt"));
  o.csv = a.text_or("--csv", "");
  o.plots = a.text_or("--plots", "");
  a.finish();
  // Step counts derive their levels from V_min/V_max, so they are applied last.
  auto is_count = [](const auto& kv) {
    return kv.first.ends_with("_steps") && kv.first != "steps";
  };
  std::stable_partition(sets.begin(), sets.end(), [&](const auto& kv) { return !is_count(kv); });
  for (const auto& [name, val] : sets) walking::set_parameter(o.params, name, val);
  walking::validate(o.params);
  if (o.csv.empty() && o.plots.empty()) throw Error("nothing to write: give --csv and/or --plots");
  return o;
}

using Frame = walking::PatternFrame;  // one sampled instant with its leg joints

plot::Table walk_table(const std::vector<Frame>& walk) {
  plot::Table t{{"time", "waist_x", "waist_y", "waist_z", "left_x", "left_y", "left_z", "right_x",
                 "right_y", "right_z", "zmp_x", "zmp_y"}};
  for (std::string_view n : walking::kLegJointNames) t.columns.emplace_back(n);
  t.columns.insert(t.columns.end(), {"support", "waist_vx", "waist_vy", "waist_vz"});
  for (const Frame& f : walk) {
    const PatternSample& s = f.s;
    std::vector<double> row = {s.t,
                               s.waist.x(),
                               s.waist.y(),
                               s.waist.z(),
                               s.left_foot.x(),
                               s.left_foot.y(),
                               s.left_foot.z(),
                               s.right_foot.x(),
                               s.right_foot.y(),
                               s.right_foot.z(),
                               s.zmp.x(),
                               s.zmp.y()};
    row.insert(row.end(), f.q.left.begin(), f.q.left.end());
    row.insert(row.end(), f.q.right.begin(), f.q.right.end());
    row.insert(row.end(), {static_cast<double>(s.support), s.waist_velocity.x(),
                           s.waist_velocity.y(), s.waist_velocity.z()});
    t.add_row(std::move(row));
  }
  return t;
}

// Figures gnuplot_plot.hpp's 2-D line plots cannot draw (3-D curve, stick diagram).
std::string terminal_line(const std::string& png) {
  const std::string term = plot::png_terminal();
  if (term.empty()) throw Error("gnuplot with a png terminal not found (install gnuplot-nox)");
  return "set terminal " + term + " size 900,600\nset output '" + png + "'\nset grid\n";
}

// Fig. 3.18: hip-knee-ankle sticks of one leg every `every` frames, in the sagittal plane.
void stick_diagram(const std::vector<Frame>& walk, model::Side side, const std::string& dir,
                   const std::string& stem, int every) {
  const std::string dat = dir + "/" + stem + ".dat";
  std::ostringstream f;
  for (std::size_t i = 0; i < walk.size(); i += every) {
    const auto& q = side == model::Side::Left ? walk[i].q.left : walk[i].q.right;
    const walking::LegPoints l = walking::leg_points(side, q, walk[i].s.waist);
    for (const Eigen::Vector3d& p : {l.hip, l.knee, l.ankle}) f << p.x() << ' ' << p.z() << '\n';
    f << '\n';  // a blank line ends one stick
  }
  write_file(dat, f.str());
  plot::run_gnuplot(dir + "/" + stem + ".gp",
                    terminal_line(dir + "/" + stem + ".png") + "set title '" + stem +
                        ": hip, knee, ankle (Fig. 3.18)' noenhanced\nset xlabel 'x [m]'\n"
                        "set ylabel 'z [m]'\nset size ratio -1\nplot '" +
                        dat + "' with linespoints lw 1 pt 7 ps 0.3 notitle\n",
                    dir + "/" + stem + ".png");
}

void write_plots(const std::vector<Frame>& walk, const walking::PatternParameters& p,
                 const std::string& dir) {
  console::make_output_dir("--plots", dir);
  const std::string csv = dir + "/pattern.csv";
  plot::write_csv(csv, walk_table(walk));
  auto line_plot = [&](const std::string& stem, const std::string& x,
                       std::vector<plot::Series> series, const std::string& title,
                       const std::string& x_label, const std::string& y_label,
                       const std::string& x_range = "") {
    plot::render_png({.csv_path = csv,
                      .x_column = x,
                      .series = std::move(series),
                      .title = title,
                      .x_label = x_label,
                      .y_label = y_label,
                      .png_path = dir + "/" + stem + ".png",
                      .x_range = x_range});
  };
  line_plot("fig3_8_waist_velocity", "time", {{"waist_vx", "waist forward velocity"}},
            "Fig. 3.8: forward waist velocity", "t [s]", "[m/s]");
  line_plot("fig3_10_lateral_first_step", "time", {{"waist_y", "waist y"}},
            "Fig. 3.10: lateral waist trajectory, first step (Eq. 3.7, Eq. 3.8)", "t [s]", "[m]",
            "[0:" + std::to_string(p.T_step()) + "]");
  line_plot("fig3_15_forward", "time",
            {{"waist_x", "waist"}, {"left_x", "left foot"}, {"right_x", "right foot"}},
            "Fig. 3.15: waist and feet, forward direction", "t [s]", "x [m]");
  line_plot("fig3_16_transverse", "waist_x", {{"waist_y", "waist"}, {"zmp_y", "ZMP", "zmp_x"}},
            "Fig. 3.16: waist and ZMP, transverse plane", "x [m]", "y [m]");
  line_plot("fig3_16_sagittal", "time", {{"waist_z", "waist height"}},
            "Fig. 3.16: waist, sagittal plane", "t [s]", "z [m]");
  line_plot("fig3_17_knees", "time", {{"LKneePitch", "left knee"}, {"RKneePitch", "right knee"}},
            "Fig. 3.17: knee pitch", "t [s]", "[rad]");
  plot::run_gnuplot(dir + "/fig3_14_waist_3d.gp",
                    terminal_line(dir + "/fig3_14_waist_3d.png") +
                        "set datafile separator ','\nset title 'Fig. 3.14: waist trajectory'\n"
                        "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset zlabel 'z [m]'\n"
                        "set ticslevel 0\nsplot '" +
                        csv + "' skip 1 using 2:3:4 with lines lw 2 title 'waist'\n",
                    dir + "/fig3_14_waist_3d.png");
  const int every = std::max(1, static_cast<int>(walk.size() / 150));
  stick_diagram(walk, model::Side::Left, dir, "fig3_18_stick_left", every);
  stick_diagram(walk, model::Side::Right, dir, "fig3_18_stick_right", every);
}

// `--set ?`: the settable parameters with their values in the chosen preset.
int list_parameters(Args args, std::ostream& out) {
  walking::PatternParameters p;
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == "--preset") p = walking::preset(args[i + 1]);
  out << "pattern parameters (--set name=value; value [unit] in range: meaning):\n";
  for (const auto& line : walking::parameter_lines(p)) out << "  " << line << "\n";
  return kExitOk;
}

}  // namespace

int pattern_main(Args args, std::ostream& out, std::ostream& err) {
  if (args.empty()) {
    err << kUsage << "\n";
    return kExitUsage;
  }
  try {
    if (asks_for_settings(args)) return list_parameters(args, out);
  } catch (const Error& e) {
    return report_error(UsageError(e.what()), err, "stride pattern: ");
  }
  PatternOptions o;
  std::vector<Frame> walk;
  try {
    o = parse_options(args);
    if (!o.csv.empty()) console::check_output_file("--csv", o.csv);
    if (!o.plots.empty()) console::check_output_dir("--plots", o.plots);
    walk = walking::sample_pattern(o.params, o.conventional, o.dt);
  } catch (const Error& e) {
    return report_error(UsageError(e.what()), err, "stride pattern: ");
  }
  try {
    if (!o.csv.empty()) {
      plot::Table t = walk_table(walk);
      t.columns.resize(12 + 12);  // the documented columns; pattern.csv under --plots has more
      for (auto& row : t.rows) row.resize(24);
      plot::write_csv(o.csv, t);
    }
    if (!o.plots.empty()) write_plots(walk, o.params, o.plots);
  } catch (const Error& e) {
    err << "stride pattern: " << e.what() << "\n";
    return 1;
  }
  const walking::PatternSummary r = walking::summarize_pattern(walk);
  out << (o.conventional ? "conventional" : "stretched-knee") << " pattern: " << o.params.steps + 1
      << " foot steps in " << r.duration << " s, " << r.distance << " m, "
      << r.distance / r.duration << " m/s mean, " << r.distance / (o.params.steps + 1)
      << " m per step; worst ZMP margin to the support polygon " << r.worst_zmp_margin
      << " m; smallest support knee " << r.min_support_knee << " rad; " << r.unreachable
      << " samples out of the legs' reach\n";
  for (const std::string& note : walking::plausibility_notes(o.params))
    out << "note: " << note << "\n";
  if (r.unreachable == 0) return 0;
  err << "stride pattern: " << r.unreachable
      << " samples put a foot beyond its leg's reach (the IK clamped them)\n";
  return 1;
}

}  // namespace stride::cli
