#include "console/experiments/arm_swing_experiment.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "console/experiments/walk_pool.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {

int run_arm_swing_experiment(const ExperimentOptions& o, std::ostream& out) {
  const bool files = prepare_out_dir(o);
  // Fig. 4.18's average speeds and step lengths (top, middle, bottom).
  struct Row {
    double speed, step;
  };
  const Row thesis[] = {{0.1095, 0.0270}, {0.1571, 0.0388}, {0.1940, 0.0479}};
  std::vector<std::vector<std::string>> rows;
  plot::Table fig{{"t", "left_1", "right_1", "left_2", "right_2", "left_3", "right_3"}};
  std::vector<std::vector<double>> left(3), right(3);
  std::vector<double> times;
  std::vector<WalkSetup> setups;
  for (const Row& t : thesis) {
    WalkSetup setup{scene_path(o, "hip_medium"), 1};
    std::ostringstream p;
    p << "steps=80 A_l=0.001 V_min=" << t.speed - 0.005 << " V_max=" << t.speed + 0.005;
    setup.parameters = {{"PatternWalk", p.str()}, {"ArmSwing", "gain_scale=1"}};
    setup.settle_seconds = 0.05;
    setups.push_back(setup);
  }
  record_walks(setups, o.jobs, [&](std::size_t i, WalkRecording&& r) {
    const WalkSummary s = summarize(r);
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
  out << "Arm swing (Sec. 4.4, Eq. 4.20), hip strategy on the uneven floor, 80 waist steps\n";
  print_table(out,
              {"target v", "v [m/s]", "step [m]", "steps", "shoulder amp [rad]", "fell", "thesis v",
               "thesis step"},
              rows);
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
