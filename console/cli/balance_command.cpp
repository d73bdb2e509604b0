// `stride balance <what> ...`: the balance analyses of thesis Ch. 7 from the command line.
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "behaviours/balance/lipm_solution.hpp"
#include "behaviours/balance/lqr_balance.hpp"
#include "behaviours/balance/strategy_classifier.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/plot/run_figures.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

namespace {
using namespace stride::balance;

constexpr const char* kUsage =
    "usage: stride balance classify|ankle-boundaries|closed-loop|hip|combined|lqr "
    "[--x0 m] [--v0 m/s] [--kp] [--kd] [--x-set] [--g] [--z] [--mass] [--zmp-min] [--zmp-max] "
    "[--inertia] [--tau-f] [--tau-b] [--theta-max-f] [--theta-max-b] [--theta0] [--theta-dot0] "
    "[--q a,b,c,d] [--r a,b] [--duration s] [--dt s] [--json] [--csv out.csv] [--plots dir]";

struct Options {
  std::string what;
  BalanceParams p;
  std::optional<double> x0, v0;
  PdGains gains{72, 12};
  double x_set = 0.0;
  std::optional<double> duration;
  double dt = 1e-3;
  std::vector<double> q{2000, 500, 1, 10}, r{4500000, 100};  // Figs. 7.13-7.14
  bool json = false;
  std::string csv, plots;
};

double parse_number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v))
    throw UsageError(flag + " expects a number, got '" + text + "'");
  return v;
}

std::vector<double> parse_list(const std::string& flag, const std::string& text, std::size_t n) {
  std::vector<double> out;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) out.push_back(parse_number(flag, item));
  if (out.size() != n)
    throw UsageError(flag + " expects " + std::to_string(n) + " comma-separated numbers, got '" +
                     text + "'");
  return out;
}

Options parse(Args args) {
  if (args.empty()) throw Error("missing <what>; " + std::string(kUsage));
  Options o;
  o.what = args[0];
  std::map<std::string, std::function<void(const std::string&)>> numeric = {
      {"--x0", [&](auto& s) { o.x0 = parse_number("--x0", s); }},
      {"--v0", [&](auto& s) { o.v0 = parse_number("--v0", s); }},
      {"--kp", [&](auto& s) { o.gains.kp = parse_number("--kp", s); }},
      {"--kd", [&](auto& s) { o.gains.kd = parse_number("--kd", s); }},
      {"--x-set", [&](auto& s) { o.x_set = parse_number("--x-set", s); }},
      {"--g", [&](auto& s) { o.p.g = parse_number("--g", s); }},
      {"--z", [&](auto& s) { o.p.z_cm = parse_number("--z", s); }},
      {"--mass", [&](auto& s) { o.p.mass = parse_number("--mass", s); }},
      {"--zmp-min", [&](auto& s) { o.p.zmp_min = parse_number("--zmp-min", s); }},
      {"--zmp-max", [&](auto& s) { o.p.zmp_max = parse_number("--zmp-max", s); }},
      {"--inertia", [&](auto& s) { o.p.inertia = parse_number("--inertia", s); }},
      {"--tau-f", [&](auto& s) { o.p.tau_forward = parse_number("--tau-f", s); }},
      {"--tau-b", [&](auto& s) { o.p.tau_backward = parse_number("--tau-b", s); }},
      {"--theta-max-f", [&](auto& s) { o.p.theta_max_forward = parse_number("--theta-max-f", s); }},
      {"--theta-max-b",
       [&](auto& s) { o.p.theta_max_backward = parse_number("--theta-max-b", s); }},
      {"--theta0", [&](auto& s) { o.p.theta0 = parse_number("--theta0", s); }},
      {"--theta-dot0", [&](auto& s) { o.p.theta_dot0 = parse_number("--theta-dot0", s); }},
      {"--duration", [&](auto& s) { o.duration = parse_number("--duration", s); }},
      {"--dt", [&](auto& s) { o.dt = parse_number("--dt", s); }},
      {"--q", [&](auto& s) { o.q = parse_list("--q", s, 4); }},
      {"--r", [&](auto& s) { o.r = parse_list("--r", s, 2); }},
      {"--csv", [&](auto& s) { o.csv = s; }},
      {"--plots", [&](auto& s) { o.plots = s; }},
  };
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--json") {
      o.json = true;
      continue;
    }
    const auto it = numeric.find(a);
    if (it == numeric.end()) throw UsageError("unknown argument '" + a + "'");
    if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
    it->second(args[++i]);
  }
  validate(o.p);
  if (!(o.dt > 0) || o.dt > 0.1) throw UsageError("--dt expects a step in (0, 0.1] s");
  if (o.duration && (!(*o.duration > 0) || *o.duration > 60))
    throw UsageError("--duration expects a time in (0, 60] s");
  if (o.duration && *o.duration / o.dt > 2e6)
    throw UsageError("--duration / --dt: too many samples");
  if (o.x0.has_value() != o.v0.has_value() && o.what != "classify")
    throw UsageError("--x0 and --v0 go together");
  return o;
}

using plot::Figure;
using plot::Run;

struct Report {
  std::ostringstream text;
  std::vector<std::pair<std::string, std::string>> json;  // key -> JSON value
  plot::RunSet set;                                       // columns: first is "t"
  std::vector<Figure> figures;
};

std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string state_name(const ComState& s) {
  return "(" + num(s.x) + "," + num(s.v) + ")";
}

std::vector<ComState> cases(const Options& o, std::vector<ComState> thesis_defaults) {
  if (o.v0) return {ComState{o.x0.value_or(0.0), *o.v0}};
  return thesis_defaults;
}

std::string plan_json(const BangBangPlan& b) {
  return "{\"recoverable\": " + std::string(b.recoverable ? "true" : "false") +
         ", \"zmp\": " + num(b.zmp) + ", \"tau\": " + num(b.profile.tau) +
         ", \"t1\": " + num(b.profile.t1) + ", \"t2\": " + num(b.profile.t2) +
         ", \"theta_peak\": " + num(b.theta_peak) + "}";
}

std::string interval_json(const CaptureInterval& c) {
  return "[" + num(c.lo) + ", " + num(c.hi) + "]";
}

void add_bang_bang_runs(Report& rep, const Options& o, const std::vector<ComState>& states,
                        bool combined) {
  rep.set.columns = {"t", "x", "v", "theta", "theta_dot", "tau", "zmp"};
  const double T = o.duration.value_or(1.5);
  std::ostringstream cases_json;
  for (const ComState& s : states) {
    const BangBangPlan plan = combined ? plan_combined(o.p, s) : plan_hip(o.p, s);
    Run run{state_name(s), {}};
    for (long i = 0; i * o.dt <= T + 1e-12; ++i) {
      const double t = i * o.dt;
      const HipModelState h = bang_bang_state(o.p, s, plan, t);
      run.rows.push_back({t, h.x, h.v, h.theta, h.theta_dot, h.tau, plan.zmp});
    }
    rep.set.runs.push_back(std::move(run));
    rep.text << "  " << state_name(s) << ": capture point " << num(plan.capture_point) << ", "
             << (plan.recoverable ? "recoverable" : "NOT recoverable") << ", zmp " << num(plan.zmp)
             << ", tau " << num(plan.profile.tau) << " N m, t1 " << num(plan.profile.t1)
             << " s, t2 " << num(plan.profile.t2) << " s, theta(t2) " << num(plan.theta_peak)
             << " rad\n";
    cases_json << (cases_json.tellp() ? ", " : "") << "{\"x0\": " << num(s.x)
               << ", \"v0\": " << num(s.v) << ", \"plan\": " << plan_json(plan) << "}";
  }
  rep.json.push_back({"cases", "[" + cases_json.str() + "]"});
}

Report run_command(const Options& o) {
  Report rep;
  const BalanceParams& p = o.p;
  const double w = p.omega();
  rep.json.push_back({"command", "\"" + o.what + "\""});
  rep.json.push_back({"omega", num(w)});
  const PhaseLine l1 = ankle_front_boundary(p), l2 = ankle_back_boundary(p);
  if (o.what == "classify") {
    const ComState s{o.x0.value_or(0.0), o.v0.value_or(0.0)};
    const Classification c = classify(p, s);
    auto vel = [&](const CaptureInterval& i) {
      return "xdot0 in [" + num(w * (i.lo - s.x)) + ", " + num(w * (i.hi - s.x)) + "]";
    };
    rep.text << "state " << state_name(s) << ", omega " << num(w) << " 1/s, capture point "
             << num(c.capture_point) << " m\n"
             << "  ankle    capture point in [" << num(c.ankle.lo) << ", " << num(c.ankle.hi)
             << "] (" << vel(c.ankle) << "): " << (c.ankle_recovers ? "recovers" : "no") << "\n"
             << "  hip      capture point in [" << num(c.hip.lo) << ", " << num(c.hip.hi) << "] ("
             << vel(c.hip) << "): " << (c.hip_recovers ? "recovers" : "no") << ", t1 "
             << num(c.hip_plan.profile.t1) << " s, t2 " << num(c.hip_plan.profile.t2) << " s\n"
             << "  combined capture point in [" << num(c.combined.lo) << ", " << num(c.combined.hi)
             << "] (" << vel(c.combined) << "): " << (c.combined_recovers ? "recovers" : "no")
             << ", zmp " << num(c.combined_plan.zmp) << " m, t1 " << num(c.combined_plan.profile.t1)
             << " s, t2 " << num(c.combined_plan.profile.t2) << " s\n"
             << "strategy: " << to_string(c.strategy) << "\n";
    rep.json.push_back({"x0", num(s.x)});
    rep.json.push_back({"v0", num(s.v)});
    rep.json.push_back({"capture_point", num(c.capture_point)});
    rep.json.push_back({"strategy", "\"" + std::string(to_string(c.strategy)) + "\""});
    rep.json.push_back({"ankle", "{\"interval\": " + interval_json(c.ankle) +
                                     ", \"recoverable\": " + (c.ankle_recovers ? "true" : "false") +
                                     "}"});
    rep.json.push_back({"hip", "{\"interval\": " + interval_json(c.hip) +
                                   ", \"plan\": " + plan_json(c.hip_plan) + "}"});
    rep.json.push_back({"combined", "{\"interval\": " + interval_json(c.combined) +
                                        ", \"plan\": " + plan_json(c.combined_plan) + "}"});
    Options sub = o;
    sub.v0 = s.v;
    sub.x0 = s.x;
    if (c.strategy == Strategy::ankle) {
      rep.set.columns = {"t", "x", "v", "zmp"};
      Run run{state_name(s), {}};
      for (long i = 0; i * o.dt <= o.duration.value_or(1.5) + 1e-12; ++i) {
        const ComState st = lipm_state(s, w, c.ankle_result.forcing, i * o.dt);
        run.rows.push_back({i * o.dt, st.x, st.v, c.ankle_result.zmp});
      }
      rep.set.runs.push_back(std::move(run));
    } else {
      Report tmp;
      add_bang_bang_runs(tmp, sub, {s}, c.strategy != Strategy::hip);
      rep.set.columns = tmp.set.columns;
      rep.set.runs = std::move(tmp.set.runs);
    }
    rep.figures.push_back({"classify_com",
                           "CoM, " + std::string(to_string(c.strategy)) + " strategy",
                           "t [s]",
                           "x [m]",
                           {"x"},
                           "",
                           "",
                           {}});
  } else if (o.what == "ankle-boundaries") {
    rep.text << "open-loop ankle strategy (Eq. 7.13), omega " << num(w) << " 1/s\n"
             << "  l1: xdot = " << num(l1.slope) << " x + " << num(l1.intercept)
             << "  (ZMP at the front border " << num(p.zmp_max) << " m)\n"
             << "  l2: xdot = " << num(l2.slope) << " x + " << num(l2.intercept)
             << "  (ZMP at the back border " << num(p.zmp_min) << " m)\n";
    rep.json.push_back(
        {"l1", "{\"slope\": " + num(l1.slope) + ", \"intercept\": " + num(l1.intercept) + "}"});
    rep.json.push_back(
        {"l2", "{\"slope\": " + num(l2.slope) + ", \"intercept\": " + num(l2.intercept) + "}"});
    std::vector<ComState> grid;
    for (int k = -5; k <= 8; ++k) grid.push_back({0.0, 0.1 * k});
    rep.set.columns = {"t", "x", "v", "zmp"};
    for (const ComState& s : cases(o, grid)) {
      const AnkleOpenLoopResult a = ankle_open_loop(p, s);
      Run run{state_name(s) + (a.recoverable ? " stable" : " falls"), {}};
      for (long i = 0; i * o.dt <= o.duration.value_or(0.6) + 1e-12; ++i) {
        const ComState st = lipm_state(s, w, a.forcing, i * o.dt);
        run.rows.push_back({i * o.dt, st.x, st.v, a.zmp});
      }
      rep.set.runs.push_back(std::move(run));
      rep.text << "  " << state_name(s) << ": capture point " << num(a.capture_point) << " -> "
               << (a.recoverable ? "recoverable" : "falls") << ", zmp " << num(a.zmp) << "\n";
    }
    rep.figures.push_back({"fig7_4_phase",
                           "Ankle strategy, open loop (Fig. 7.4)",
                           "x [m]",
                           "xdot [m/s]",
                           {},
                           "x",
                           "v",
                           {{"l1", l1.slope, l1.intercept}, {"l2", l2.slope, l2.intercept}},
                           "[-0.3:0.3]",
                           "[-1:1.2]"});
  } else if (o.what == "closed-loop") {
    const ClosedLoopBoundaries c = closed_loop_boundaries(p, o.gains, o.x_set);
    rep.text << "PD closed loop kp " << num(o.gains.kp) << ", kd " << num(o.gains.kd)
             << " (Eqs. 7.16-7.20): k1 " << num(c.k1) << ", k2 " << num(c.k2) << "\n";
    std::ostringstream lines_json;
    for (const auto& [n, l] : {std::pair{"l1", c.l1}, {"l2", c.l2}, {"a", c.a}, {"b", c.b}}) {
      rep.text << "  " << n << ": xdot = " << num(l.slope) << " x + " << num(l.intercept) << "\n";
      lines_json << (lines_json.tellp() ? ", " : "") << "\"" << n
                 << "\": {\"slope\": " << num(l.slope) << ", \"intercept\": " << num(l.intercept)
                 << "}";
    }
    for (const auto& [n, pt] : {std::pair{"A", c.A}, {"B", c.B}, {"C", c.C}, {"D", c.D}}) {
      rep.text << "  " << n << " = " << (pt ? state_name({pt->x, pt->v}) : "none (parallel)")
               << "\n";
      lines_json << ", \"" << n << "\": "
                 << (pt ? "[" + num(pt->x) + ", " + num(pt->v) + "]" : std::string("null"));
    }
    rep.json.push_back({"k1", num(c.k1)});
    rep.json.push_back({"k2", num(c.k2)});
    rep.json.push_back({"boundaries", "{" + lines_json.str() + "}"});
    rep.set.columns = {"t", "x", "v", "zmp", "demanded_zmp", "ankle_torque"};
    std::ostringstream cases_json;
    for (const ComState& s : cases(o, {{-0.4, 2.3}, {0.42, -2.3}, {-0.32, 2.3}, {0.37, -2.3}})) {
      const ClosedLoopRun r =
          simulate_closed_loop(p, o.gains, s, o.x_set, o.duration.value_or(3.0), o.dt);
      Run run{state_name(s), {}};
      for (const ClosedLoopSample& q : r.samples)
        run.rows.push_back({q.t, q.x, q.v, q.zmp, q.demanded_zmp, q.ankle_torque});
      rep.set.runs.push_back(std::move(run));
      rep.text << "  " << state_name(s) << ": " << (r.converged ? "converges" : "diverges")
               << (r.saturated ? " (ZMP saturated at the sole border)" : "") << "\n";
      cases_json << (cases_json.tellp() ? ", " : "") << "{\"x0\": " << num(s.x)
                 << ", \"v0\": " << num(s.v)
                 << ", \"converged\": " << (r.converged ? "true" : "false")
                 << ", \"saturated\": " << (r.saturated ? "true" : "false") << "}";
    }
    rep.json.push_back({"cases", "[" + cases_json.str() + "]"});
    rep.figures.push_back({"fig7_5_lines",
                           "PD closed loop: boundaries and trajectories (Figs. 7.5-7.6)",
                           "x [m]",
                           "xdot [m/s]",
                           {},
                           "x",
                           "v",
                           {{"l1", c.l1.slope, c.l1.intercept},
                            {"l2", c.l2.slope, c.l2.intercept},
                            {"a", c.a.slope, c.a.intercept},
                            {"b", c.b.slope, c.b.intercept}},
                           "[-0.6:0.6]",
                           "[-3:3]"});
    rep.figures.push_back({"fig7_7_zmp",
                           "ZMP during PD recovery (Fig. 7.7)",
                           "t [s]",
                           "ZMP [m]",
                           {"zmp"},
                           "",
                           "",
                           {}});
    rep.figures.push_back({"fig7_7_torque",
                           "Ankle torque during PD recovery (Fig. 7.7)",
                           "t [s]",
                           "tau_a [N m]",
                           {"ankle_torque"},
                           "",
                           "",
                           {}});
  } else if (o.what == "hip" || o.what == "combined") {
    const bool combined = o.what == "combined";
    const HipBoundaries h = hip_boundaries(p);
    const CombinedBoundaries cb = combined_boundaries(p);
    const double lo = combined ? cb.backward : h.backward, hi = combined ? cb.forward : h.forward;
    rep.text << (combined ? "combined strategy (Eq. 7.37)" : "pure hip strategy (Eq. 7.30)")
             << ": recoverable for capture point in [" << num(lo) << ", " << num(hi) << "] m\n"
             << "  forward limit profile t1 " << num(h.forward_profile.t1) << " s, t2 "
             << num(h.forward_profile.t2) << " s; backward t1 " << num(h.backward_profile.t1)
             << " s, t2 " << num(h.backward_profile.t2) << " s\n";
    rep.json.push_back({"interval", "[" + num(lo) + ", " + num(hi) + "]"});
    add_bang_bang_runs(
        rep, o,
        cases(o, combined ? std::vector<ComState>{{0, 0.8}, {0, 1.1}}
                          : std::vector<ComState>{{-0.1, 0.7}, {0.1, -0.6}, {0, -0.55}, {0, 0.8}}),
        combined);
    const std::string fig = combined ? "fig7_11" : "fig7_9";
    const std::string tag = combined ? " (Fig. 7.11)" : " (Fig. 7.9)";
    rep.figures.push_back(
        {fig + "_com", "CoM" + tag, "t [s]", "x [m]", {"x"}, "", "", {}, "", "[-0.4:0.4]"});
    rep.figures.push_back(
        {fig + "_hip_angle", "Hip angle" + tag, "t [s]", "theta [rad]", {"theta"}, "", "", {}});
    rep.figures.push_back({fig + "_hip_rate",
                           "Hip angular velocity" + tag,
                           "t [s]",
                           "thetadot [rad/s]",
                           {"theta_dot"},
                           "",
                           "",
                           {}});
    rep.figures.push_back(
        {fig + "_hip_torque", "Hip torque" + tag, "t [s]", "tau_h [N m]", {"tau"}, "", "", {}});
  } else if (o.what == "lqr") {
    const LqrBalanceModel m = lqr_balance_model(p);
    const Eigen::Matrix4d Q = Eigen::Vector4d(o.q[0], o.q[1], o.q[2], o.q[3]).asDiagonal();
    const Eigen::Matrix2d R = Eigen::Vector2d(o.r[0], o.r[1]).asDiagonal();
    const LqrSolution sol = lqr(m.A, m.B, Q, R);
    const Eigen::Vector4d x0(o.x0.value_or(0.0), p.theta0, o.v0.value_or(0.9475), p.theta_dot0);
    const auto samples = simulate_lqr(m, sol.K, x0, o.duration.value_or(3.0), o.dt);
    Eigen::IOFormat fmt(8, 0, ", ", "\n", "    [", "]");
    rep.text << "LQR (Eqs. 7.38-7.39), x0 = [x, theta, xdot, thetadot] = ["
             << x0.transpose().format(Eigen::IOFormat(8, 0, ", ")) << "]\n"
             << "  K =\n"
             << sol.K.format(fmt) << "\n  S =\n"
             << sol.S.format(fmt) << "\n  closed-loop poles: " << sol.closed_loop_poles.transpose()
             << "\n  CARE residual norm: " << num(care_residual(m.A, m.B, Q, R, sol.S).norm())
             << "\n";
    rep.set.columns = {"t", "x", "theta", "xdot", "thetadot", "zmp", "tau"};
    Run run{"lqr", {}};
    double peak[6] = {0, 0, 0, 0, 0, 0};
    for (const LqrSample& s : samples) {
      run.rows.push_back(
          {s.t, s.state(0), s.state(1), s.state(2), s.state(3), s.input(0), s.input(1)});
      for (int i = 0; i < 6; ++i) peak[i] = std::max(peak[i], std::abs(run.rows.back()[i + 1]));
    }
    rep.text << "  peaks: |x| " << num(peak[0]) << " m, |theta| " << num(peak[1]) << " rad, |zmp| "
             << num(peak[4]) << " m, |tau| " << num(peak[5]) << " N m; final |state| "
             << num(samples.back().state.norm()) << "\n";
    std::ostringstream k;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 4; ++j) k << (i || j ? ", " : "") << num(sol.K(i, j));
    rep.json.push_back({"K", "[" + k.str() + "]"});
    rep.json.push_back({"max_pole_real", num(sol.closed_loop_poles.real().maxCoeff())});
    rep.json.push_back({"peak_x", num(peak[0])});
    rep.json.push_back({"peak_theta", num(peak[1])});
    rep.json.push_back({"peak_zmp", num(peak[4])});
    rep.json.push_back({"peak_tau", num(peak[5])});
    rep.json.push_back({"final_state_norm", num(samples.back().state.norm())});
    rep.set.runs.push_back(std::move(run));
    rep.figures.push_back(
        {"fig7_13_com", "CoM under LQR (Fig. 7.13)", "t [s]", "x [m]", {"x"}, "", "", {}});
    rep.figures.push_back({"fig7_14_state",
                           "LQR state (Fig. 7.14)",
                           "t [s]",
                           "state",
                           {"x", "theta", "xdot", "thetadot"},
                           "",
                           "",
                           {}});
    rep.figures.push_back(
        {"fig7_14_inputs", "LQR inputs (Fig. 7.14)", "t [s]", "input", {"zmp", "tau"}, "", "", {}});
  } else {
    throw UsageError("unknown <what> '" + o.what + "'; " + kUsage);
  }
  return rep;
}

}  // namespace

int balance_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    Options o;
    try {
      o = parse(args);
    } catch (const UsageError&) {
      throw;
    } catch (const Error& e) {
      throw UsageError(e.what());  // a bad flag value, e.g. parameters that fail validation
    }
    const Report rep = run_command(o);
    if (!o.csv.empty()) plot::write_long_csv(rep.set, o.csv);
    if (!o.plots.empty()) {
      std::error_code ec;
      std::filesystem::create_directories(o.plots, ec);
      if (ec) throw Error("--plots: cannot create directory '" + o.plots + "'");
      for (const Figure& f : rep.figures) plot::write_figure(rep.set, f, o.plots);
    }
    if (o.json) {
      out << "{";
      for (std::size_t i = 0; i < rep.json.size(); ++i)
        out << (i ? ", " : "") << "\"" << rep.json[i].first << "\": " << rep.json[i].second;
      out << "}\n";
    } else {
      out << rep.text.str();
      if (!o.plots.empty()) out << "plots written to " << o.plots << "\n";
    }
    return 0;
  } catch (const Error& e) {
    return report_error(e, err, "stride balance: ");
  }
}

}  // namespace stride::cli
