#include "console/experiments/gains_experiment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <ostream>
#include <sstream>
#include <vector>

#include "console/experiments/parameter_overrides.hpp"
#include "console/experiments/torso_sway.hpp"
#include "console/experiments/walk_pool.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

struct Strategy {
  const char* name;    // scene prefix
  const char* module;  // PostureCorrectedRequest provider
  const char* figure;
  double kp, kd;  // the figure's gains
};
constexpr Strategy kStrategies[] = {{"hip", "HipStrategy", "Fig. 4.7", 0.40, -0.05},
                                    {"ankle", "AnkleStrategy", "Fig. 4.11", 0.28, -0.06}};

struct Setting {
  const Strategy* strategy;
  bool kp_sweep;  // K_p swept at the figure's K_d, or K_d at the figure's K_p
  double kp, kd;
};

struct GainStats {  // one setting over the seeds
  int walks = 0, lost = 0;
  double lean = 0, sway = 0, shake = 0, roll_sd = 0, kept_distance = 0;
};

std::vector<Setting> settings() {
  std::vector<Setting> s;
  for (const Strategy& st : kStrategies) {
    std::vector<double> kps{0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8};
    std::vector<double> kds{0.0, -0.02, -0.04, -0.05, -0.06, -0.08, -0.10, -0.15};
    if (std::find(kps.begin(), kps.end(), st.kp) == kps.end())  // the figure's own gain, in order
      kps.insert(std::upper_bound(kps.begin(), kps.end(), st.kp), st.kp);
    if (std::find(kds.begin(), kds.end(), st.kd) == kds.end())
      kds.insert(std::upper_bound(kds.begin(), kds.end(), st.kd, std::greater<>()), st.kd);
    for (double kp : kps) s.push_back({&st, true, kp, st.kd});
    for (double kd : kds) s.push_back({&st, false, st.kp, kd});
  }
  return s;
}

// Two strategies' (x, y1, y2) curves as the columns of one table, the shorter padded with NaN.
plot::Table side_by_side(std::vector<std::string> columns,
                         const std::vector<std::array<double, 3>>& hip,
                         const std::vector<std::array<double, 3>>& ankle) {
  plot::Table t{std::move(columns)};
  for (std::size_t i = 0; i < std::max(hip.size(), ankle.size()); ++i) {
    std::vector<double> row;
    for (const auto* c : {&hip, &ankle})
      for (int j = 0; j < 3; ++j) row.push_back(i < c->size() ? (*c)[i][j] : NAN);
    t.add_row(std::move(row));
  }
  return t;
}

}  // namespace

WalkSetup gains_walk(const ExperimentOptions& o, const std::string& strategy, double kp, double kd,
                     std::uint64_t seed) {
  const Strategy* st = nullptr;
  for (const Strategy& s : kStrategies)
    if (strategy == s.name) st = &s;
  if (!st) throw Error("stride experiment gains: unknown strategy '" + strategy + "' (hip, ankle)");
  WalkSetup setup{scene_path(o, strategy + "_medium"), seed};
  std::ostringstream p;
  p << "kp_pitch=" << kp << " kd_pitch=" << kd << " kp_roll=" << kp << " kd_roll=" << kd;
  setup.parameters = {{st->module, p.str()}};
  return with_overrides(o, setup);
}

int run_gains_experiment(const ExperimentOptions& o, std::ostream& out) {
  const bool files = prepare_out_dir(o);
  const int seeds = o.seeds > 0 ? o.seeds : 3;
  const std::vector<Setting> grid = settings();
  std::vector<WalkSetup> setups;
  for (const Setting& s : grid)
    for (int seed = 1; seed <= seeds; ++seed)
      setups.push_back(
          gains_walk(o, s.strategy->name, s.kp, s.kd, static_cast<std::uint64_t>(seed)));
  std::vector<GainStats> stats(grid.size());
  record_walks(setups, o.jobs, [&](std::size_t i, WalkRecording&& r) {
    GainStats& g = stats[i / seeds];
    const WalkSummary s = summarize(r);
    const TorsoSway w = torso_sway(r);  // up to a fall: the walk's sway, not the fall's
    ++g.walks;
    g.lean += w.pitch_mean, g.sway += w.pitch_sd, g.shake += w.pitch_rate_rms;
    g.roll_sd += w.roll_sd;
    if (s.fell || s.tipped != sim::Tip::None) {
      ++g.lost;
    } else {
      g.kept_distance += s.distance;
    }
    return true;
  });
  plot::Table table{{"strategy", "sweep", "kp", "kd", "walks", "lost", "lean_rad", "sway_rad",
                     "shake_rad_s", "roll_sd_rad", "kept_distance_m"}};
  // One figure per sweep: per strategy its own x column (the swept gain) and two curves.
  std::vector<std::array<double, 3>> curves[2][2];  // [kp sweep?][ankle?] -> (x, y1, y2)
  std::vector<std::vector<std::string>> rows;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Setting& set = grid[k];
    const GainStats& g = stats[k];
    const double n = g.walks;
    const double lean = g.lean / n, sway = g.sway / n, shake = g.shake / n;
    const int kept = g.walks - g.lost;
    const double dist = kept > 0 ? g.kept_distance / kept : NAN;
    const bool ankle = set.strategy != &kStrategies[0];
    table.add_row({ankle ? 1.0 : 0.0, set.kp_sweep ? 0.0 : 1.0, set.kp, set.kd, n, double(g.lost),
                   lean, sway, shake, g.roll_sd / n, dist});
    curves[set.kp_sweep][ankle].push_back(
        {set.kp_sweep ? set.kp : set.kd, set.kp_sweep ? lean : shake, sway});
    const bool thesis = set.kp == set.strategy->kp && set.kd == set.strategy->kd;
    rows.push_back({set.strategy->name, set.kp_sweep ? "K_p" : "K_d", fixed(set.kp, 2),
                    fixed(set.kd, 2), std::to_string(g.walks), std::to_string(g.lost),
                    fixed(lean, 4), fixed(sway, 4), fixed(shake, 3), fixed(g.roll_sd / n, 4),
                    fixed(dist, 3), thesis ? set.strategy->figure : ""});
  }
  const plot::Table kp_fig =
      side_by_side({"hip_kp", "hip_lean", "hip_sway", "ankle_kp", "ankle_lean", "ankle_sway"},
                   curves[1][0], curves[1][1]);
  const plot::Table kd_fig =
      side_by_side({"hip_kd", "hip_shake", "hip_sway", "ankle_kd", "ankle_shake", "ankle_sway"},
                   curves[0][0], curves[0][1]);
  out << "PD gains of the posture strategies (Sec. 4.3.4.2), medium speed on the uneven floor, "
      << seeds
      << " seed(s) per setting; pitch and roll take the same gains.\n"
         "lean = mean torso pitch while walking (> 0 forward), sway = its standard deviation, "
         "shake = pitch-rate RMS before any fall; lost = fell or past "
      << sim::kTipAngle << " rad\n";
  print_table(out,
              {"strategy", "sweep", "K_p", "K_d", "walks", "lost", "lean[rad]", "sway[rad]",
               "shake[rad/s]", "roll sd[rad]", "kept dist[m]", "thesis"},
              rows);
  out << "Thesis (hip strategy): the torso leans back as K_p rises and oscillates when it is too "
         "large; at K_d <= -0.06 it shakes.\n";
  if (files) {
    plot::write_csv(o.out_dir + "/gains.csv", table);
    write_plot(o, kp_fig, "gains_kp",
               "Torso lean and sway against K_p (K_d: hip -0.05, ankle -0.06)", "hip_kp",
               {{"hip_lean", "hip: lean (mean pitch)", "hip_kp"},
                {"hip_sway", "hip: sway (pitch sd)", "hip_kp"},
                {"ankle_lean", "ankle: lean", "ankle_kp"},
                {"ankle_sway", "ankle: sway", "ankle_kp"}},
               "K_p", "[rad]", "linespoints");
    write_plot(o, kd_fig, "gains_kd", "Torso shake against K_d (K_p: hip 0.40, ankle 0.28)",
               "hip_kd",
               {{"hip_shake", "hip: shake (pitch-rate RMS) [rad/s]", "hip_kd"},
                {"hip_sway", "hip: sway (pitch sd) [rad]", "hip_kd"},
                {"ankle_shake", "ankle: shake [rad/s]", "ankle_kd"},
                {"ankle_sway", "ankle: sway [rad]", "ankle_kd"}},
               "K_d", "", "linespoints");
  }
  return 0;
}

}  // namespace stride::experiments
