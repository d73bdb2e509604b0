#include "console/experiments/arm_swing_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "console/experiments/parameter_overrides.hpp"
#include "console/experiments/walk_pool.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

namespace {

struct YawStats {  // one speed, arm swing on or off, over the seeds
  int walks = 0, fell = 0, stances = 0;
  double spin = 0, spin_max = 0, yaw_span = 0;
};

}  // namespace

WalkSetup arm_swing_walk(const ExperimentOptions& o, double target_speed, bool swing,
                         std::uint64_t seed) {
  WalkSetup setup{scene_path(o, "hip_medium"), seed};
  std::ostringstream p;
  p << "steps=80 A_l=0.001 V_min=" << target_speed - 0.005 << " V_max=" << target_speed + 0.005;
  setup.parameters = {{"PatternWalk", p.str()},
                      {"ArmSwing", swing ? "gain_scale=1" : "gain_scale=0"}};
  setup.settle_seconds = 0.05;
  return with_overrides(o, setup);
}

int run_arm_swing_experiment(const ExperimentOptions& o, std::ostream& out) {
  const bool files = prepare_out_dir(o);
  const int seeds = o.seeds > 0 ? o.seeds : 1;
  // Fig. 4.18's average speeds and step lengths (top, middle, bottom).
  struct Row {
    double speed, step;
  };
  const Row thesis[] = {{0.1095, 0.0270}, {0.1571, 0.0388}, {0.1940, 0.0479}};
  std::vector<std::vector<std::string>> rows;
  plot::Table fig{{"t", "left_1", "right_1", "left_2", "right_2", "left_3", "right_3"}};
  std::vector<std::vector<double>> left(3), right(3);
  std::vector<double> times;
  // Walk k: speed k / (2 seeds), arm swing on for even k / seeds, off for odd (Sec. 4.4's question:
  // does the swing take the yaw moment off the support foot?).
  std::vector<WalkSetup> setups;
  for (const Row& t : thesis)
    for (int on = 1; on >= 0; --on)
      for (int seed = 1; seed <= seeds; ++seed)
        setups.push_back(arm_swing_walk(o, t.speed, on == 1, static_cast<std::uint64_t>(seed)));
  YawStats yaw[3][2];
  record_walks(setups, o.jobs, [&](std::size_t k, WalkRecording&& r) {
    const std::size_t i = k / (2 * seeds);
    const bool on = (k / seeds) % 2 == 0;
    const bool first = k % seeds == 0;
    const WalkSummary s = summarize(r);
    YawStats& y = yaw[i][on ? 1 : 0];
    ++y.walks;
    if (s.fell) {
      ++y.fell;  // a fall turns the feet as it likes: count it, keep it out of the means
    } else {
      y.stances += s.steps;
      y.spin += r.metrics.foot_spin;
      y.spin_max = std::max(y.spin_max, r.metrics.foot_spin_max);
      y.yaw_span += r.metrics.yaw_max - r.metrics.yaw_min;
    }
    if (!on || !first) return true;
    for (const auto& row : r.trace.rows) {
      if (row[col(Trace::pattern_t)] < 0) continue;
      if (i == 0) times.push_back(row[col(Trace::pattern_t)]);
      left[i].push_back(row[col(Trace::shoulder_pitch_l)]);
      right[i].push_back(row[col(Trace::shoulder_pitch_r)]);
    }
    const auto [lo, hi] = std::minmax_element(left[i].begin(), left[i].end());
    const double amplitude = 0.5 * (*hi - *lo);
    rows.push_back({fixed(thesis[i].speed, 4), fixed(s.speed, 4), fixed(s.step_length, 4),
                    std::to_string(s.steps), fixed(amplitude, 4), s.fell ? "yes" : "no",
                    fixed(thesis[i].speed, 4), fixed(thesis[i].step, 4)});
    return true;
  });
  for (std::size_t k = 0; k < times.size(); ++k) {
    std::vector<double> row{times[k]};
    for (int i = 0; i < 3; ++i) {
      row.push_back(k < left[i].size() ? left[i][k] : NAN);
      row.push_back(k < right[i].size() ? right[i][k] : NAN);
    }
    fig.add_row(std::move(row));
  }
  out << "Arm swing (Sec. 4.4, Eq. 4.20), hip strategy on the uneven floor, 80 waist steps, seed "
         "1\n";
  print_table(out,
              {"target v", "v [m/s]", "step [m]", "steps", "shoulder amp [rad]", "fell", "thesis v",
               "thesis step"},
              rows);
  // The support foot's yaw turn per stance is what the swing is meant to remove (Eq. 4.18 = 0).
  out << "\nYaw moment (Sec. 4.4): support-foot turn per stance and torso heading span, mean over "
      << seeds << " seed(s), walks that fell left out\n";
  std::vector<std::vector<std::string>> yaw_rows;
  plot::Table yaw_table{{"target_v", "arm_swing", "walks", "fell", "spin_per_step_mrad",
                         "spin_max_rad", "torso_yaw_span_rad"}};
  for (int i = 0; i < 3; ++i)
    for (int on = 1; on >= 0; --on) {
      const YawStats& y = yaw[i][on];
      const double per_step = y.stances > 0 ? 1000 * y.spin / y.stances : NAN;
      const double span = y.walks > y.fell ? y.yaw_span / (y.walks - y.fell) : NAN;
      yaw_rows.push_back({fixed(thesis[i].speed, 4), on ? "on" : "off", std::to_string(y.walks),
                          std::to_string(y.fell), fixed(per_step, 1), fixed(y.spin_max, 3),
                          fixed(span, 3)});
      yaw_table.add_row({thesis[i].speed, double(on), double(y.walks), double(y.fell), per_step,
                         y.spin_max, span});
    }
  print_table(out,
              {"target v", "arm swing", "walks", "fell", "foot turn/step [mrad]",
               "max one stance [rad]", "torso yaw span [rad]"},
              yaw_rows);
  if (files) plot::write_csv(o.out_dir + "/arm_swing_yaw.csv", yaw_table);
  if (files)
    write_plot(o, fig, "arm_swing_fig4.18", "Compensating shoulder pitch angles (Fig. 4.18)", "t",
               {{"left_1", "left, 0.11 m/s", ""},
                {"right_1", "right, 0.11 m/s", ""},
                {"left_2", "left, 0.157 m/s", ""},
                {"right_2", "right, 0.157 m/s", ""},
                {"left_3", "left, 0.194 m/s", ""},
                {"right_3", "right, 0.194 m/s", ""}},
               "t [s]", "shoulder pitch [rad]");
  return 0;
}

}  // namespace stride::experiments
