// `stride swing-leg <study> [--controller adaptive|pd|both] [--seconds S] [--dt s] [--csv dir]
// [--plots dir]`: the Ch. 5 swing-leg studies (adaptive vs PD control on the App. C models), and
// `stride swing-leg ode-track [--scene f] [--seconds S] [--preset P]` on the simulated NAO.
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>

#include "behaviours/swing_leg/thesis_runs.hpp"
#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/experiments/swing_leg_ode_study.hpp"
#include "console/output/output_paths.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "console/progress/progress_line.hpp"
#include "console/session/headless_run.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"
#include "robot/framework/enum_names.hpp"
#include "robot/nao/nao_dimensions.hpp"

namespace stride::cli {
namespace {

using swing_leg::Controller;

std::string controller_name(Controller c) {
  return std::string(enum_name(c));
}

// A torque no NAO joint can give is flagged beside the figure: the motors' largest stall torque
// at the joint with margin.
std::string torque_note(double torque) {
  constexpr double kLargestStall = nao::kLargestStallTorque;
  if (torque <= 2 * kLargestStall) return "";
  std::ostringstream s;
  s << "  (!) " << std::setprecision(3) << torque / kLargestStall
    << " x the largest NAO joint's stall torque (" << kLargestStall << " N m)";
  return s.str();
}

std::string row(const Eigen::VectorXd& v) {
  std::ostringstream s;
  s << std::scientific << std::setprecision(2);
  for (Eigen::Index i = 0; i < v.size(); ++i) s << (i ? " " : "") << v[i];
  return s.str();
}

// One CSV per controller: time, desired and actual angles, errors, torques, estimates.
plot::Table table_of(const swing_leg::TrackingResult& r, swing_leg::LegModel m) {
  const auto names = swing_leg::joint_names(m);
  plot::Table t;
  t.columns.push_back("t");
  for (const auto& n : names) t.columns.push_back(n + "_desired");
  for (const auto& n : names) t.columns.push_back(n);
  for (const auto& n : names) t.columns.push_back(n + "_error");
  for (const auto& n : names) t.columns.push_back(n + "_torque");
  for (int i = 0; i < swing_leg::parameter_count(m); ++i)
    t.columns.push_back("a" + std::to_string(i + 1));
  t.columns.push_back("lyapunov");
  for (const auto& s : r.samples) {
    std::vector<double> v{s.t};
    for (Eigen::Index i = 0; i < s.q.size(); ++i) v.push_back(s.q_desired[i]);
    for (Eigen::Index i = 0; i < s.q.size(); ++i) v.push_back(s.q[i]);
    for (Eigen::Index i = 0; i < s.q.size(); ++i) v.push_back(s.q[i] - s.q_desired[i]);
    for (Eigen::Index i = 0; i < s.q.size(); ++i) v.push_back(s.tau[i]);
    for (Eigen::Index i = 0; i < s.a_hat.size(); ++i) v.push_back(s.a_hat[i]);
    v.push_back(s.lyapunov);
    t.add_row(std::move(v));
  }
  return t;
}

void render(const std::string& csv, std::vector<plot::Series> series, const std::string& title,
            const std::string& y_label, const std::string& png,
            std::vector<plot::Reference> references = {}) {
  plot::PlotSpec spec;
  spec.references = std::move(references);
  spec.csv_path = csv;
  spec.x_column = "t";
  spec.series = std::move(series);
  spec.title = title;
  spec.x_label = "t [s]";
  spec.y_label = y_label;
  spec.png_path = png;
  plot::render_png(spec);
}

void plots(const std::string& dir, const std::string& stem, const std::string& csv,
           swing_leg::LegModel m, Controller c, const swing_leg::TrackingResult& r) {
  const auto names = swing_leg::joint_names(m);
  const std::string who = controller_name(c);
  const auto series = [&](const std::string& suffix) {
    std::vector<plot::Series> s;
    for (const auto& n : names) s.push_back({n + suffix, n + suffix, ""});
    return s;
  };
  std::vector<plot::Series> tracking;
  for (const auto& n : names) {
    tracking.push_back({n + "_desired", n + " desired", ""});
    tracking.push_back({n, n, ""});
  }
  render(csv, tracking, stem + " " + who + ": tracking", "angle [rad]",
         dir + "/" + stem + "_" + who + "_tracking.png");
  render(csv, series("_error"), stem + " " + who + ": tracking error", "q - q_d [rad]",
         dir + "/" + stem + "_" + who + "_error.png");
  render(csv, series("_torque"), stem + " " + who + ": control torque", "tau [N m]",
         dir + "/" + stem + "_" + who + "_torque.png");
  if (c != Controller::Adaptive) return;
  // The last three groups are m b g moments [N m], the others inertias [kg m^2] (App. C); each
  // estimate is drawn against its true value, dashed in the same colour.
  const int p = swing_leg::parameter_count(m);
  std::vector<plot::Series> inertial, gravitational;
  std::vector<plot::Reference> inertial_true, gravitational_true;
  for (int i = 1; i <= p; ++i) {
    const bool g = i > p - 3;
    auto& series = g ? gravitational : inertial;
    const std::string name = "a" + std::to_string(i);
    (g ? gravitational_true : inertial_true)
        .push_back(
            {r.true_parameters[i - 1], name + " true", false, static_cast<int>(series.size())});
    series.push_back({name, name + " estimate", ""});
  }
  render(csv, inertial, stem + ": inertial parameter estimates", "a [kg m^2]",
         dir + "/" + stem + "_inertial_estimates.png", inertial_true);
  render(csv, gravitational, stem + ": gravitational parameter estimates", "a [N m]",
         dir + "/" + stem + "_gravitational_estimates.png", gravitational_true);
}

// Sec. 5.4.2: both laws on the simulated NAO over a grid of gains a 1 kHz torque loop allows.
int ode_track(ArgumentReader& a, std::ostream& out) {
  experiments::OdeSwingLegOptions o;
  o.scene = a.has("--scene") ? a.text("--scene") : data_file("scenes/swing_leg/hanging_nao.xml");
  o.duration =
      console::checked_run_seconds(a.number_or("--seconds", 10), "stride swing-leg: --seconds");
  o.preset = a.text_or("--preset", "medium");
  const double gamma_scale = a.number_or("--gamma-scale", 1.0);
  if (!(gamma_scale > 0)) throw UsageError("stride swing-leg: --gamma-scale: expected > 0");
  o.gamma = experiments::thesis_ode_gamma() * gamma_scale;
  a.finish();
  out << "swing-leg ode-track (Sec. 5.4.2, Figs. 5.13-5.14): " << o.scene << ", left leg in torque "
      << "mode tracking the '" << o.preset << "' pattern for " << o.duration
      << " s at 1 kHz, errors after 1 s, Gamma = " << gamma_scale << " x the thesis' Sec. 5.4.2\n";
  out << "lambda  K_D   controller  rms error [rad] (hip roll .. ankle roll)        max |tau|  "
         "beyond stall\n";
  const std::pair<double, double> grid[] = {{10, 0.05}, {20, 0.1}, {40, 0.1}, {20, 0.2}};
  console::ProgressLine progress(
      std::cerr, {.label = "swing-leg ode-track", .total = 2.0 * std::size(grid), .unit = "runs"},
      console::progress_settings());
  for (const auto& [lambda, kd] : grid)
    for (Controller c : {Controller::Adaptive, Controller::Pd}) {
      o.lambda = lambda;
      o.kd = kd;
      o.controller = c;
      const auto r = experiments::run_ode_swing_leg(o);
      out << std::fixed << std::setprecision(2) << std::setw(6) << lambda << "  " << kd << "  "
          << std::left << std::setw(10) << controller_name(c) << std::right << "  "
          << row(r.rms_error) << "  " << std::fixed << std::setprecision(2) << r.max_torque
          << " N m  " << std::setprecision(1) << 100 * r.saturated << " %"
          << torque_note(r.max_torque) << "\n";
      progress.advance();
    }
  return 0;
}

}  // namespace

int swing_leg_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    ArgumentReader a(args, "swing-leg");
    const std::string study = a.positional("study");
    if (study == "ode-track") return ode_track(a, out);
    swing_leg::ThesisRun run = [&] {
      try {
        return swing_leg::thesis_run(study);
      } catch (const Error& e) {
        throw UsageError(e.what());  // an unknown study is a wrong command line
      }
    }();
    const std::string which = a.text_or("--controller", "both");
    if (which != "adaptive" && which != "pd" && which != "both")
      throw UsageError("stride swing-leg: --controller: expected adaptive, pd or both");
    run.options.duration = console::checked_run_seconds(
        a.number_or("--seconds", run.options.duration), "stride swing-leg: --seconds");
    run.options.dt = a.number_or("--dt", run.options.dt);
    const std::string csv_dir = a.text_or("--csv", "");
    const std::string plot_dir = a.text_or("--plots", "");
    a.finish();
    if (!csv_dir.empty()) console::make_output_dir("stride swing-leg: --csv", csv_dir);
    if (!plot_dir.empty()) console::make_output_dir("stride swing-leg: --plots", plot_dir);

    const auto m = run.options.model;
    out << "swing-leg " << run.name << " (" << run.figures << "), " << run.options.duration
        << " s, dt " << run.options.dt * 1000 << " ms, lambda " << run.options.lambda << ", K_D "
        << run.options.kd << "\n";
    out << "joints: ";
    for (const auto& n : swing_leg::joint_names(m)) out << n << " ";
    out << "\n";
    for (Controller c : {Controller::Adaptive, Controller::Pd}) {
      if (which != "both" && which != controller_name(c)) continue;
      run.options.controller = c;
      const swing_leg::TrackingResult r = swing_leg::simulate_tracking(run.options, run.reference);
      out << std::left << std::setw(9) << controller_name(c) << " rms error [rad] "
          << row(r.rms_error) << "  last fifth " << row(r.late_rms_error) << "  max "
          << row(r.max_error) << "  max |tau| " << std::fixed << std::setprecision(1)
          << r.max_torque << " N m" << torque_note(r.max_torque) << "\n";
      if (c == Controller::Adaptive)
        out << "          a (true)  " << row(r.true_parameters) << "\n"
            << "          a^ (end)  " << row(r.final_estimate) << "\n";
      const std::string stem = run.name;
      const std::string dir = !csv_dir.empty() ? csv_dir : plot_dir;
      if (dir.empty()) continue;
      const std::string csv = dir + "/" + stem + "_" + controller_name(c) + ".csv";
      plot::write_csv(csv, table_of(r, m));
      if (!plot_dir.empty() && !plot::png_terminal().empty()) plots(plot_dir, stem, csv, m, c, r);
    }
    return 0;
  } catch (const Error& e) {
    return report_error(e, err);
  }
}

}  // namespace stride::cli
