#include "console/experiments/balance_analyses.hpp"

#include <cmath>
#include <tuple>
#include <utility>

#include "behaviours/balance/lipm_solution.hpp"
#include "behaviours/balance/lqr_balance.hpp"
#include "behaviours/balance/strategy_classifier.hpp"
#include "robot/core/error.hpp"
#include "robot/core/quote.hpp"

namespace stride::experiments {

namespace {
using namespace stride::balance;
using Options = BalanceAnalysisOptions;
using Report = BalanceReport;
using plot::Figure;
using plot::Run;

std::string num(double v) {
  if (!std::isfinite(v)) return "null";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// The support polygon's borders the ZMP stays within (Sec. 7.2), drawn beside ZMP curves.
std::vector<plot::Reference> sole_borders(const BalanceParams& p) {
  return {{p.zmp_max, "front border of the sole"}, {p.zmp_min, "back border of the sole"}};
}

std::string state_name(const ComState& s) {
  return "(" + num(s.x) + "," + num(s.v) + ")";
}

std::vector<ComState> cases(const Options& o, std::vector<ComState> thesis_defaults) {
  if (o.v0) return {ComState{o.x0.value_or(0.0), *o.v0}};
  return thesis_defaults;
}

void write_plan(JsonWriter& j, const BangBangPlan& b) {
  j.begin_object().field("recoverable", b.recoverable).field("zmp", b.zmp);
  j.field("tau", b.profile.tau).field("t1", b.profile.t1).field("t2", b.profile.t2);
  j.field("theta_peak", b.theta_peak).end_object();
}

void write_interval(JsonWriter& j, double lo, double hi) {
  j.begin_array().value(lo).value(hi).end_array();
}

void write_line(JsonWriter& j, const char* name, const PhaseLine& l) {
  j.key(name).begin_object().field("slope", l.slope).field("intercept", l.intercept).end_object();
}

// The CoM of the LIPM from `s` under the ankle strategy's constant ZMP, sampled every dt.
Run ankle_run(const Options& o, const std::string& name, const ComState& s, double forcing,
              double zmp, double duration) {
  Run run{name, {}};
  for (long i = 0; i * o.dt <= duration + 1e-12; ++i) {
    const ComState st = lipm_state(s, o.p.omega(), forcing, i * o.dt);
    run.rows.push_back({i * o.dt, st.x, st.v, zmp});
  }
  return run;
}

void add_bang_bang_runs(Report& rep, const Options& o, const std::vector<ComState>& states,
                        bool combined) {
  rep.set.columns = {"t", "x", "v", "theta", "theta_dot", "tau", "zmp"};
  const double T = o.duration.value_or(1.5);
  rep.json.key("cases").begin_array();
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
    rep.json.begin_object().field("x0", s.x).field("v0", s.v).key("plan");
    write_plan(rep.json, plan);
    rep.json.end_object();
  }
  rep.json.end_array();
}

void classify_text(Report& rep, const Options& o, const ComState& s, const Classification& c) {
  const double w = o.p.omega();
  auto vel = [&](const CaptureInterval& i) {
    return "xdot0 in [" + num(w * (i.lo - s.x)) + ", " + num(w * (i.hi - s.x)) + "]";
  };
  rep.text << "state " << state_name(s) << ", omega " << num(w) << " 1/s, capture point "
           << num(c.capture_point) << " m\n"
           << "  ankle    capture point in [" << num(c.ankle.lo) << ", " << num(c.ankle.hi) << "] ("
           << vel(c.ankle) << "): " << (c.ankle_recovers ? "recovers" : "no") << "\n"
           << "  hip      capture point in [" << num(c.hip.lo) << ", " << num(c.hip.hi) << "] ("
           << vel(c.hip) << "): " << (c.hip_recovers ? "recovers" : "no") << ", t1 "
           << num(c.hip_plan.profile.t1) << " s, t2 " << num(c.hip_plan.profile.t2) << " s\n"
           << "  combined capture point in [" << num(c.combined.lo) << ", " << num(c.combined.hi)
           << "] (" << vel(c.combined) << "): " << (c.combined_recovers ? "recovers" : "no")
           << ", zmp " << num(c.combined_plan.zmp) << " m, t1 " << num(c.combined_plan.profile.t1)
           << " s, t2 " << num(c.combined_plan.profile.t2) << " s\n"
           << "strategy: " << to_string(c.strategy) << "\n";
}

void classify_json(Report& rep, const ComState& s, const Classification& c) {
  rep.json.field("x0", s.x).field("v0", s.v).field("capture_point", c.capture_point);
  rep.json.field("strategy", to_string(c.strategy));
  rep.json.key("ankle").begin_object().key("interval");
  write_interval(rep.json, c.ankle.lo, c.ankle.hi);
  rep.json.field("recoverable", c.ankle_recovers).end_object();
  for (const auto& [name, interval, plan] :
       {std::tuple{"hip", c.hip, c.hip_plan}, {"combined", c.combined, c.combined_plan}}) {
    rep.json.key(name).begin_object().key("interval");
    write_interval(rep.json, interval.lo, interval.hi);
    rep.json.key("plan");
    write_plan(rep.json, plan);
    rep.json.end_object();
  }
}

void classify(Report& rep, const Options& o) {
  const ComState s{o.x0.value_or(0.0), o.v0.value_or(0.0)};
  const Classification c = balance::classify(o.p, s);
  classify_text(rep, o, s, c);
  classify_json(rep, s, c);
  Options sub = o;
  sub.v0 = s.v;
  sub.x0 = s.x;
  if (c.strategy == Strategy::ankle) {
    rep.set.columns = {"t", "x", "v", "zmp"};
    rep.set.runs.push_back(ankle_run(o, state_name(s), s, c.ankle_result.forcing,
                                     c.ankle_result.zmp, o.duration.value_or(1.5)));
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
}

void ankle_boundaries(Report& rep, const Options& o) {
  const BalanceParams& p = o.p;
  const PhaseLine l1 = ankle_front_boundary(p), l2 = ankle_back_boundary(p);
  rep.text << "open-loop ankle strategy (Eq. 7.13), omega " << num(p.omega()) << " 1/s\n"
           << "  l1: xdot = " << num(l1.slope) << " x + " << num(l1.intercept)
           << "  (ZMP at the front border " << num(p.zmp_max) << " m)\n"
           << "  l2: xdot = " << num(l2.slope) << " x + " << num(l2.intercept)
           << "  (ZMP at the back border " << num(p.zmp_min) << " m)\n";
  write_line(rep.json, "l1", l1);
  write_line(rep.json, "l2", l2);
  std::vector<ComState> grid;
  for (int k = -5; k <= 8; ++k) grid.push_back({0.0, 0.1 * k});
  rep.set.columns = {"t", "x", "v", "zmp"};
  for (const ComState& s : cases(o, grid)) {
    const AnkleOpenLoopResult a = ankle_open_loop(p, s);
    rep.set.runs.push_back(ankle_run(o, state_name(s) + (a.recoverable ? " stable" : " falls"), s,
                                     a.forcing, a.zmp, o.duration.value_or(0.6)));
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
}

void closed_loop_boundaries_report(Report& rep, const Options& o, const ClosedLoopBoundaries& c) {
  rep.text << "PD closed loop kp " << num(o.gains.kp) << ", kd " << num(o.gains.kd)
           << " (Eq. 7.16, Eq. 7.18, Eq. 7.20): k1 " << num(c.k1) << ", k2 " << num(c.k2) << "\n";
  rep.json.field("k1", c.k1).field("k2", c.k2).key("boundaries").begin_object();
  for (const auto& [n, l] : {std::pair{"l1", c.l1}, {"l2", c.l2}, {"a", c.a}, {"b", c.b}}) {
    rep.text << "  " << n << ": xdot = " << num(l.slope) << " x + " << num(l.intercept) << "\n";
    rep.json.key(n).begin_object().field("slope", l.slope).field("intercept", l.intercept);
    rep.json.end_object();
  }
  for (const auto& [n, pt] : {std::pair{"A", c.A}, {"B", c.B}, {"C", c.C}, {"D", c.D}}) {
    rep.text << "  " << n << " = " << (pt ? state_name({pt->x, pt->v}) : "none (parallel)") << "\n";
    rep.json.key(n);
    if (pt)
      write_interval(rep.json, pt->x, pt->v);  // the point (x, xdot)
    else
      rep.json.null();
  }
  rep.json.end_object();
}

void closed_loop_runs(Report& rep, const Options& o) {
  rep.set.columns = {"t", "x", "v", "zmp", "demanded_zmp", "ankle_torque"};
  rep.json.key("cases").begin_array();
  for (const ComState& s : cases(o, {{-0.4, 2.3}, {0.42, -2.3}, {-0.32, 2.3}, {0.37, -2.3}})) {
    const ClosedLoopRun r =
        simulate_closed_loop(o.p, o.gains, s, o.x_set, o.duration.value_or(3.0), o.dt);
    Run run{state_name(s), {}};
    for (const ClosedLoopSample& q : r.samples)
      run.rows.push_back({q.t, q.x, q.v, q.zmp, q.demanded_zmp, q.ankle_torque});
    rep.set.runs.push_back(std::move(run));
    rep.text << "  " << state_name(s) << ": " << (r.converged ? "converges" : "diverges")
             << (r.saturated ? " (ZMP saturated at the sole border)" : "") << "\n";
    rep.json.begin_object().field("x0", s.x).field("v0", s.v);
    rep.json.field("converged", r.converged).field("saturated", r.saturated).end_object();
  }
  rep.json.end_array();
}

void closed_loop(Report& rep, const Options& o) {
  const ClosedLoopBoundaries c = closed_loop_boundaries(o.p, o.gains, o.x_set);
  closed_loop_boundaries_report(rep, o, c);
  closed_loop_runs(rep, o);
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
  rep.figures.push_back({.stem = "fig7_7_zmp",
                         .title = "ZMP during PD recovery (Fig. 7.7)",
                         .x_label = "t [s]",
                         .y_label = "ZMP [m]",
                         .quantities = {"zmp"},
                         .references = sole_borders(o.p)});
  rep.figures.push_back({"fig7_7_torque",
                         "Ankle torque during PD recovery (Fig. 7.7)",
                         "t [s]",
                         "tau_a [N m]",
                         {"ankle_torque"},
                         "",
                         "",
                         {}});
}

void hip_figures(Report& rep, const BalanceParams& p, bool combined) {
  const std::string fig = combined ? "fig7_11" : "fig7_9";
  const std::string tag = combined ? " (Fig. 7.11)" : " (Fig. 7.9)";
  rep.figures.push_back(
      {fig + "_com", "CoM" + tag, "t [s]", "x [m]", {"x"}, "", "", {}, "", "[-0.4:0.4]"});
  rep.figures.push_back({.stem = fig + "_hip_angle",
                         .title = "Hip angle" + tag,
                         .x_label = "t [s]",
                         .y_label = "theta [rad]",
                         .quantities = {"theta"},
                         .references = {{p.theta_max_forward, "hip pitch limit, forward"},
                                        {p.theta_max_backward, "hip pitch limit, backward"}}});
  rep.figures.push_back({fig + "_hip_rate",
                         "Hip angular velocity" + tag,
                         "t [s]",
                         "thetadot [rad/s]",
                         {"theta_dot"},
                         "",
                         "",
                         {}});
  rep.figures.push_back({.stem = fig + "_hip_torque",
                         .title = "Hip torque" + tag,
                         .x_label = "t [s]",
                         .y_label = "tau_h [N m]",
                         .quantities = {"tau"},
                         .references = {{p.tau_forward, "tau_n-f, forward recovery"},
                                        {p.tau_backward, "tau_n-b, backward recovery"}}});
}

void hip_or_combined(Report& rep, const Options& o) {
  const bool combined = o.what == "combined";
  const HipBoundaries h = hip_boundaries(o.p);
  const CombinedBoundaries cb = combined_boundaries(o.p);
  const double lo = combined ? cb.backward : h.backward, hi = combined ? cb.forward : h.forward;
  rep.text << (combined ? "combined strategy (Eq. 7.37)" : "pure hip strategy (Eq. 7.30)")
           << ": recoverable for capture point in [" << num(lo) << ", " << num(hi) << "] m\n"
           << "  forward limit profile t1 " << num(h.forward_profile.t1) << " s, t2 "
           << num(h.forward_profile.t2) << " s; backward t1 " << num(h.backward_profile.t1)
           << " s, t2 " << num(h.backward_profile.t2) << " s\n";
  rep.json.key("interval");
  write_interval(rep.json, lo, hi);
  add_bang_bang_runs(
      rep, o,
      cases(o, combined ? std::vector<ComState>{{0, 0.8}, {0, 1.1}}
                        : std::vector<ComState>{{-0.1, 0.7}, {0.1, -0.6}, {0, -0.55}, {0, 0.8}}),
      combined);
  hip_figures(rep, o.p, combined);
}

void lqr_figures(Report& rep, const BalanceParams& p) {
  rep.figures.push_back(
      {"fig7_13_com", "CoM under LQR (Fig. 7.13)", "t [s]", "x [m]", {"x"}, "", "", {}});
  Figure state{.stem = "fig7_14_state", .title = "LQR state (Fig. 7.14)", .x_label = "t [s]"};
  state.panels = {{"x [m]", {"x"}, {}},
                  {"theta [rad]", {"theta"}, {}},
                  {"xdot [m/s]", {"xdot"}, {}},
                  {"thetadot [rad/s]", {"thetadot"}, {}}};
  rep.figures.push_back(state);
  Figure inputs{.stem = "fig7_14_inputs", .title = "LQR inputs (Fig. 7.14)", .x_label = "t [s]"};
  inputs.panels = {{"ZMP [m]", {"zmp"}, sole_borders(p)},
                   {"tau_h [N m]",
                    {"tau"},
                    {{p.tau_forward, "hip torque, forward recovery"},
                     {p.tau_backward, "hip torque, backward recovery"}}}};
  rep.figures.push_back(inputs);
}

void lqr_json(Report& rep, const LqrSolution& sol, const double (&peak)[6], double final_norm) {
  rep.json.key("K").begin_array();  // row by row
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 4; ++j) rep.json.value(sol.K(i, j));
  rep.json.end_array();
  rep.json.field("max_pole_real", sol.closed_loop_poles.real().maxCoeff());
  rep.json.field("peak_x", peak[0]).field("peak_theta", peak[1]);
  rep.json.field("peak_zmp", peak[4]).field("peak_tau", peak[5]);
  rep.json.field("final_state_norm", final_norm);
}

void lqr_analysis(Report& rep, const Options& o) {
  const BalanceParams& p = o.p;
  const LqrBalanceModel m = lqr_balance_model(p);
  const Eigen::Matrix4d Q = Eigen::Vector4d(o.q[0], o.q[1], o.q[2], o.q[3]).asDiagonal();
  const Eigen::Matrix2d R = Eigen::Vector2d(o.r[0], o.r[1]).asDiagonal();
  const LqrSolution sol = lqr(m.A, m.B, Q, R);
  const Eigen::Vector4d x0(o.x0.value_or(0.0), p.theta0, o.v0.value_or(0.9475), p.theta_dot0);
  const auto samples = simulate_lqr(m, sol.K, x0, o.duration.value_or(3.0), o.dt);
  Eigen::IOFormat fmt(8, 0, ", ", "\n", "    [", "]");
  rep.text << "LQR (Eq. 7.38, Eq. 7.39), x0 = [x, theta, xdot, thetadot] = ["
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
  lqr_json(rep, sol, peak, samples.back().state.norm());
  rep.set.runs.push_back(std::move(run));
  lqr_figures(rep, p);
}

}  // namespace

const char* balance_analysis_names() {
  return "classify|ankle-boundaries|closed-loop|hip|combined|lqr";
}

BalanceReport run_balance_analysis(const BalanceAnalysisOptions& o) {
  Report rep;
  rep.json.begin_object().field("command", o.what).field("omega", o.p.omega());
  if (o.what == "classify")
    classify(rep, o);
  else if (o.what == "ankle-boundaries")
    ankle_boundaries(rep, o);
  else if (o.what == "closed-loop")
    closed_loop(rep, o);
  else if (o.what == "hip" || o.what == "combined")
    hip_or_combined(rep, o);
  else if (o.what == "lqr")
    lqr_analysis(rep, o);
  else
    throw UsageError("unknown <what> " + quote(o.what));
  return rep;
}

}  // namespace stride::experiments
