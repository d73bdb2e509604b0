#include "console/experiments/gains_experiment.hpp"

#include <cmath>
#include <ostream>
#include <sstream>
#include <vector>

#include "console/experiments/torso_sway.hpp"
#include "console/experiments/walk_pool.hpp"

namespace stride::experiments {
namespace {

constexpr double kThesisKp = 0.40, kThesisKd = -0.05;  // Fig. 4.7

struct Setting {
  const char* sweep;
  double kp, kd;
};

struct GainStats {  // one setting over the seeds
  int walks = 0, lost = 0, kept = 0;
  double lean = 0, sway = 0, shake = 0, roll_sd = 0, kept_distance = 0;
};

std::vector<Setting> settings() {
  std::vector<Setting> s;
  for (double kp : {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8}) s.push_back({"K_p", kp, kThesisKd});
  for (double kd : {0.0, -0.02, -0.04, -0.05, -0.06, -0.08, -0.10, -0.15})
    s.push_back({"K_d", kThesisKp, kd});
  return s;
}

}  // namespace

WalkSetup gains_walk(const ExperimentOptions& o, double kp, double kd, std::uint64_t seed) {
  WalkSetup setup{scene_path(o, "hip_medium"), seed};
  std::ostringstream p;
  p << "kp_pitch=" << kp << " kd_pitch=" << kd << " kp_roll=" << kp << " kd_roll=" << kd;
  setup.parameters = {{"HipStrategy", p.str()}};
  return setup;
}

int run_gains_experiment(const ExperimentOptions& o, std::ostream& out) {
  const bool files = prepare_out_dir(o);
  const int seeds = o.seeds > 0 ? o.seeds : 3;
  const std::vector<Setting> grid = settings();
  std::vector<WalkSetup> setups;
  for (const Setting& s : grid)
    for (int seed = 1; seed <= seeds; ++seed)
      setups.push_back(gains_walk(o, s.kp, s.kd, static_cast<std::uint64_t>(seed)));
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
      ++g.kept;
      g.kept_distance += s.distance;
    }
    return true;
  });
  plot::Table table{{"sweep", "kp", "kd", "walks", "lost", "lean_rad", "sway_rad", "shake_rad_s",
                     "roll_sd_rad", "kept_distance_m"}};
  plot::Table kp_fig{{"kp", "lean", "sway"}}, kd_fig{{"kd", "shake", "sway"}};
  std::vector<std::vector<std::string>> rows;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const GainStats& g = stats[k];
    const double n = g.walks;
    const double dist = g.kept > 0 ? g.kept_distance / g.kept : NAN;
    const bool kp_sweep = grid[k].sweep[2] == 'p';
    table.add_row({kp_sweep ? 0.0 : 1.0, grid[k].kp, grid[k].kd, n, double(g.lost), g.lean / n,
                   g.sway / n, g.shake / n, g.roll_sd / n, dist});
    if (kp_sweep)
      kp_fig.add_row({grid[k].kp, g.lean / n, g.sway / n});
    else
      kd_fig.add_row({grid[k].kd, g.shake / n, g.sway / n});
    const bool thesis = grid[k].kp == kThesisKp && grid[k].kd == kThesisKd;
    rows.push_back({grid[k].sweep, fixed(grid[k].kp, 2), fixed(grid[k].kd, 2),
                    std::to_string(g.walks), std::to_string(g.lost), fixed(g.lean / n, 4),
                    fixed(g.sway / n, 4), fixed(g.shake / n, 3), fixed(g.roll_sd / n, 4),
                    fixed(dist, 3), thesis ? "Fig. 4.7" : ""});
  }
  out << "Hip strategy gains (Sec. 4.3.4.2), medium speed on the uneven floor, " << seeds
      << " seed(s) per setting; pitch and roll take the same gains.\n"
         "lean = mean torso pitch while walking (> 0 forward), sway = its standard deviation, "
         "shake = pitch-rate RMS before any fall; lost = fell or past "
      << sim::kTipAngle << " rad\n";
  print_table(out,
              {"sweep", "K_p", "K_d", "walks", "lost", "lean[rad]", "sway[rad]", "shake[rad/s]",
               "roll sd[rad]", "kept dist[m]", "thesis"},
              rows);
  out << "Thesis: the torso leans back as K_p rises and oscillates when it is too large; at K_d "
         "<= -0.06 it shakes.\n";
  if (files) {
    plot::write_csv(o.out_dir + "/gains.csv", table);
    write_plot(o, kp_fig, "gains_kp", "Hip strategy: torso lean and sway against K_p (K_d = -0.05)",
               "kp", {{"lean", "lean (mean pitch)", ""}, {"sway", "sway (pitch sd)", ""}}, "K_p",
               "[rad]", "linespoints");
    write_plot(
        o, kd_fig, "gains_kd", "Hip strategy: torso shake against K_d (K_p = 0.40)", "kd",
        {{"shake", "shake (pitch-rate RMS) [rad/s]", ""}, {"sway", "sway (pitch sd) [rad]", ""}},
        "K_d", "", "linespoints");
  }
  return 0;
}

}  // namespace stride::experiments
