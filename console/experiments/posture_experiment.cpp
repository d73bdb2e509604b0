#include "console/experiments/posture_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

#include "console/experiments/parameter_overrides.hpp"
#include "console/experiments/posture_tally.hpp"
#include "console/experiments/walk_pool.hpp"
#include "robot/core/error.hpp"
#include "robot/core/output_file.hpp"

namespace stride::experiments {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Columns `names` of the walking part of the trace (pattern_t >= -0.5 s), as a new table.
plot::Table select(const WalkRecording& r, const std::vector<Trace>& names) {
  plot::Table t;
  for (Trace c : names) t.columns.push_back(trace_columns()[col(c)]);
  for (const auto& row : r.trace.rows) {
    if (row[col(Trace::pattern_t)] < -0.5) continue;
    std::vector<double> out;
    for (Trace c : names) out.push_back(row[col(c)]);
    t.add_row(std::move(out));
  }
  return t;
}

}  // namespace

const std::vector<PostureCase>& posture_cases() {
  // Sec. 4.3.4.2: distance in 15 s, average speed and step length as printed.
  static const std::vector<PostureCase> cases = {
      {"none_slow", "-", kNaN, kNaN, kNaN},
      {"none_medium", "-", kNaN, kNaN, kNaN},
      {"none_fast", "-", kNaN, kNaN, kNaN},
      {"hip_slow", "Fig. 4.6", 1.2912, 0.0861, 0.0212},
      {"hip_medium", "Fig. 4.7", 2.8794, 0.1920, 0.0472},
      {"hip_fast", "Fig. 4.8", 3.5469, 0.2365, 0.0581},
      {"ankle_slow", "Fig. 4.10", 1.1654, 0.0777, 0.0191},
      {"ankle_medium", "Fig. 4.11", 2.6119, 0.1741, 0.0428},
      {"ankle_fast", "Fig. 4.12", 3.5035, 0.2336, 0.0574},
  };
  return cases;
}

std::vector<std::size_t> selected_posture_cases(const std::vector<std::string>& selection) {
  const auto& cases = posture_cases();
  const auto names = [](const PostureCase& c, const std::string& s) {
    return c.scene == s || c.scene.rfind(s + "_", 0) == 0;  // the scene, or its strategy
  };
  for (const std::string& s : selection)
    if (std::none_of(cases.begin(), cases.end(), [&](const PostureCase& c) { return names(c, s); }))
      throw Error("stride experiment posture: --cases: unknown case '" + s +
                  "' (expected none, hip, ankle or <strategy>_<slow|medium|fast>)");
  std::vector<std::size_t> picked;
  for (std::size_t k = 0; k < cases.size(); ++k)
    if (selection.empty() || std::any_of(selection.begin(), selection.end(),
                                         [&](const std::string& s) { return names(cases[k], s); }))
      picked.push_back(k);
  return picked;
}

void write_walk_figures(const ExperimentOptions& o, const WalkRecording& r, const std::string& stem,
                        const std::string& title, bool ankle_joints) {
  using T = Trace;
  const std::string joint = ankle_joints ? "ankle" : "hip";
  const std::vector<T> angles = ankle_joints ? std::vector<T>{T::t,
                                                              T::ankle_pitch_ref_l,
                                                              T::ankle_pitch_mod_l,
                                                              T::ankle_roll_ref_l,
                                                              T::ankle_roll_mod_l,
                                                              T::ankle_pitch_ref_r,
                                                              T::ankle_pitch_mod_r,
                                                              T::ankle_roll_ref_r,
                                                              T::ankle_roll_mod_r}
                                             : std::vector<T>{T::t,
                                                              T::hip_pitch_ref_l,
                                                              T::hip_pitch_mod_l,
                                                              T::hip_roll_ref_l,
                                                              T::hip_roll_mod_l,
                                                              T::hip_pitch_ref_r,
                                                              T::hip_pitch_mod_r,
                                                              T::hip_roll_ref_r,
                                                              T::hip_roll_mod_r};
  std::vector<plot::Series> angle_series;
  for (std::size_t i = 1; i < angles.size(); ++i)
    angle_series.push_back({trace_columns()[col(angles[i])], "", ""});
  write_plot(o, select(r, angles), stem + "_a_" + joint + "_angles",
             title + ": (a) reference and modified " + joint + " angles", "t", angle_series,
             "t [s]", "angle [rad]");
  write_plot(o, select(r, {T::t, T::true_pitch, T::true_roll, T::est_pitch, T::est_roll}),
             stem + "_b_torso", title + ": (b) torso inclination", "t",
             {{"true_pitch", "pitch (ground truth)", ""},
              {"true_roll", "roll (ground truth)", ""},
              {"est_pitch", "pitch (Kalman)", ""},
              {"est_roll", "roll (Kalman)", ""}},
             "t [s]", "[rad]");
  write_plot(o, select(r, {T::t, T::waist_v_ref, T::waist_v}), stem + "_c_waist_velocity",
             title + ": (c) waist velocity", "t",
             {{"waist_v_ref", "reference", ""}, {"waist_v", "actual (torso, ground truth)", ""}},
             "t [s]", "v_x [m/s]");
  write_plot(
      o, select(r, {T::t, T::cop_x, T::cop_y, T::zmp_ref_x, T::zmp_ref_y}), stem + "_d_zmp",
      title + ": (d) ZMP (CoP from the FSRs) in the world frame", "cop_x",
      {{"cop_y", "measured (FSR CoP)", "cop_x"}, {"zmp_ref_y", "planned (Eq. 3.16)", "zmp_ref_x"}},
      "x [m]", "y [m]", "lines");
}

namespace {

// What a posture run collects: the summary CSV, the printed rows, the per-case tallies, and the
// walks that failed (case, seed, reason).
struct PostureRun {
  plot::Table summary{
      {"case",      "seed",        "steps",     "distance",        "fk_distance",
       "speed",     "step_length", "pitch_min", "pitch_max",       "roll_min",
       "roll_max",  "fell",        "foot_slip", "foot_slip_net_x", "foot_tilted_time",
       "foot_spin", "yaw_min",     "yaw_max",   "tipped",          "tipped_at"}};
  std::vector<std::vector<std::string>> rows;
  std::vector<PostureTally> tallies = std::vector<PostureTally>(posture_cases().size());
  std::vector<std::vector<std::string>> failures;
};

// One walk's files (trace, and figures for seed 1); throws stride::Error naming a file that
// could not be written.
void write_walk_files(const ExperimentOptions& o, const PostureCase& c, int seed,
                      const WalkRecording& r) {
  const std::string suffix = seed == 1 ? "" : "_seed" + std::to_string(seed);
  plot::write_csv(o.out_dir + "/posture_" + c.scene + suffix + "_trace.csv", r.trace);
  if (seed == 1)
    write_walk_figures(o, r, "posture_" + c.scene, c.scene + " " + c.figure,
                       c.scene.rfind("ankle", 0) == 0);
}

void add_walk_row(PostureRun& run, std::size_t k, int seed, const WalkRecording& r) {
  const PostureCase& c = posture_cases()[k];
  const WalkSummary s = summarize(r);
  run.summary.add_row({double(k),
                       double(seed),
                       double(s.steps),
                       s.distance,
                       s.fk_distance,
                       s.speed,
                       s.step_length,
                       s.pitch_min,
                       s.pitch_max,
                       s.roll_min,
                       s.roll_max,
                       s.fell ? 1.0 : 0.0,
                       r.metrics.foot_slip,
                       r.metrics.foot_slip_net_x,
                       r.metrics.foot_tilted_time,
                       r.metrics.foot_spin,
                       r.metrics.yaw_min,
                       r.metrics.yaw_max,
                       double(static_cast<int>(s.tipped)),
                       s.tipped_at});
  add_walk(run.tallies[k], s);
  const std::string tipped = s.tipped == sim::Tip::None ? "-"
                                                        : std::string(sim::tip_name(s.tipped)) +
                                                              " " + fixed(s.tipped_at, 2);
  run.rows.push_back({c.scene, std::to_string(seed), std::to_string(s.steps), fixed(s.distance, 4),
                      fixed(s.fk_distance, 4), fixed(s.speed, 4), fixed(s.step_length, 4),
                      fixed(s.pitch_min, 3) + ".." + fixed(s.pitch_max, 3),
                      fixed(s.roll_min, 3) + ".." + fixed(s.roll_max, 3), s.fell ? "yes" : "no",
                      tipped, c.figure, fixed(c.thesis_distance, 4), fixed(c.thesis_speed, 4),
                      fixed(c.thesis_step, 4)});
}

// The failed walks, printed and (with --out) written as posture_failures.csv.
void report_failures(const ExperimentOptions& o, const PostureRun& run, std::size_t walks,
                     std::ostream& out) {
  if (run.failures.empty()) return;
  out << "\n" << run.failures.size() << " of " << walks << " walks failed:\n";
  print_table(out, {"case", "seed", "reason"}, run.failures);
  if (o.out_dir.empty()) return;
  std::string csv = "case,seed,reason\n";
  for (const auto& f : run.failures) {
    std::string reason = f[2];
    for (std::size_t q = reason.find('"'); q != std::string::npos; q = reason.find('"', q + 2))
      reason.insert(q, 1, '"');
    csv += f[0] + "," + f[1] + ",\"" + reason + "\"\n";
  }
  write_file(o.out_dir + "/posture_failures.csv", csv);
}

}  // namespace

int run_posture_experiment(const ExperimentOptions& o, std::ostream& out) {
  const int seeds = o.seeds > 0 ? o.seeds : 1;
  const bool files = prepare_out_dir(o);
  PostureRun run;
  const std::vector<std::size_t> picked = selected_posture_cases(o.cases);
  std::vector<WalkSetup> setups;
  for (std::size_t k : picked)
    for (int seed = 1; seed <= seeds; ++seed)
      setups.push_back(with_overrides(
          o, {scene_path(o, posture_cases()[k].scene), static_cast<std::uint64_t>(seed)}));
  // A walk that fails (a bad scene, a diverging run, an output that cannot be written) is a
  // failed row with its reason; the others go on.
  const auto failed = [&](std::size_t i, const std::string& reason) {
    run.failures.push_back(
        {posture_cases()[picked[i / seeds]].scene, std::to_string(i % seeds + 1), reason});
  };
  record_walks(
      setups, o.jobs,
      [&](std::size_t i, WalkRecording&& r) {
        const std::size_t k = picked[i / seeds];  // the summary's case column keeps table indices
        const int seed = static_cast<int>(i % seeds) + 1;
        try {
          if (files) write_walk_files(o, posture_cases()[k], seed, r);
        } catch (const Error& e) {
          failed(i, e.what());
          return true;
        }
        add_walk_row(run, k, seed, r);
        return true;
      },
      failed);
  out << "Posture control on the uneven floor, 15 s walks (Sec. 4.3.4.2); distance = ground-truth "
         "feet midpoint, fk = the thesis' FK measure\n";
  print_table(out,
              {"case", "seed", "steps", "dist[m]", "fk[m]", "v[m/s]", "step[m]", "pitch[rad]",
               "roll[rad]", "fell", "past 0.4 rad [s]", "thesis", "dist[m]", "v[m/s]", "step[m]"},
              run.rows);
  std::vector<std::vector<std::string>> tally_rows;
  for (std::size_t k : picked)
    tally_rows.push_back(
        tally_row(posture_cases()[k].scene, run.tallies[k], posture_cases()[k].thesis_distance));
  out << "\nPer case: lost = fell or torso past " << sim::kTipAngle
      << " rad (first way: fwd/back/right/left); kept walks' mean distance (ground truth, FK) "
         "and largest |pitch|\n";
  print_table(out, tally_header(), tally_rows);
  if (files) plot::write_csv(o.out_dir + "/posture_summary.csv", run.summary);
  report_failures(o, run, setups.size(), out);
  return run.failures.empty() ? 0 : 1;
}

}  // namespace stride::experiments
