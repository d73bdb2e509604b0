#include "console/experiments/knee_energy_experiment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <vector>

#include "console/experiments/parameter_overrides.hpp"
#include "console/experiments/walk_pool.hpp"

namespace stride::experiments {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One speed of Tables 4.4/4.5 with the thesis' measured speeds (mean, std in m/s) and the saving
// it printed (Sec. 4.3.4.3: 15 % and 20 % at the two lower speeds; at the higher speeds the
// conventional pattern used less, no number printed).
struct EnergySpeed {
  int cm;
  double thesis_speed_stretched, thesis_std_stretched;
  double thesis_speed_conventional, thesis_std_conventional;
  double thesis_saving;
};
constexpr EnergySpeed kSpeeds[] = {
    {5, 0.0521, 0.0023, 0.0517, 0.0017, 15},
    {10, 0.0991, 0.0069, 0.1029, 0.0053, 20},
    {15, 0.1639, 0.0053, 0.1528, 0.0072, kNaN},
    {20, 0.2004, 0.0058, 0.2020, 0.0095, kNaN},
};

struct Repeats {
  std::vector<double> speed, left, right, total;
};

std::string mean_std(std::span<const double> v, int decimals) {
  return fixed(mean_work(v), decimals) + "+-" + fixed(population_std(v), decimals);
}

}  // namespace

KneeEnergy knee_energy(const WalkRecording& r, double voltage) {
  std::vector<double> left, right;
  for (const auto& row : r.trace.rows) {
    const double tp = row[col(Trace::pattern_t)];
    if (tp < 0 || tp >= r.walk_duration - 1e-9) continue;
    left.push_back(row[col(Trace::knee_current_l)]);
    right.push_back(row[col(Trace::knee_current_r)]);
  }
  return {electrical_work(left, voltage, r.period), electrical_work(right, voltage, r.period),
          static_cast<int>(left.size())};
}

int run_knee_energy_experiment(const ExperimentOptions& o, std::ostream& out) {
  const int seeds = o.seeds > 0 ? o.seeds : 5;
  const bool files = prepare_out_dir(o);
  plot::Table walks{{"speed_cm", "conventional", "seed", "speed", "left_J", "right_J", "total_J",
                     "samples", "fell"}};
  plot::Table figure{{"speed_stretched", "left_stretched", "left_min_stretched",
                      "left_max_stretched", "right_stretched", "speed_conventional",
                      "left_conventional", "left_min_conventional", "left_max_conventional",
                      "right_conventional"}};
  std::vector<std::vector<std::string>> rows;
  int falls = 0;
  std::vector<WalkSetup> setups;
  for (const EnergySpeed& sp : kSpeeds)
    for (int conventional = 0; conventional < 2; ++conventional)
      for (int seed = 1; seed <= seeds; ++seed)
        setups.push_back(with_overrides(
            o, {scene_path(
                    o, std::string(conventional ? "energy_conventional_" : "energy_stretched_") +
                           std::to_string(sp.cm)),
                static_cast<std::uint64_t>(seed)}));
  std::vector<std::array<Repeats, 2>> repeats(std::size(kSpeeds));  // stretched, conventional
  record_walks(setups, o.jobs, [&](std::size_t i, WalkRecording&& r) {
    const std::size_t speed = i / (2 * seeds);
    const int conventional = static_cast<int>(i / seeds % 2);
    const int seed = static_cast<int>(i % seeds) + 1;
    const EnergySpeed& sp = kSpeeds[speed];
    const WalkSummary s = summarize(r);
    const KneeEnergy e = knee_energy(r);
    falls += s.fell;
    walks.add_row({double(sp.cm), double(conventional), double(seed), s.speed, e.left, e.right,
                   e.left + e.right, double(e.samples), s.fell ? 1.0 : 0.0});
    if (s.fell) return true;  // the thesis' walks were all stable: a fall is no energy sample
    Repeats& rep = repeats[speed][conventional];
    rep.speed.push_back(s.speed);
    rep.left.push_back(e.left);
    rep.right.push_back(e.right);
    rep.total.push_back(e.left + e.right);
    if (files && seed == 1 && sp.cm == 10) {  // Fig. 4.13: knee currents at 0.10 m/s
      plot::Table cur{{"t", "left", "right"}};
      for (const auto& row : r.trace.rows)
        if (row[col(Trace::pattern_t)] >= 0)
          cur.add_row({row[col(Trace::pattern_t)], row[col(Trace::knee_current_l)],
                       row[col(Trace::knee_current_r)]});
      write_plot(
          o, cur,
          std::string("energy_fig4.13_current_") + (conventional ? "conventional" : "stretched"),
          std::string("Knee currents at 0.10 m/s (") +
              (conventional ? "conventional" : "stretched-knee") + " pattern)",
          "t", {{"left", "LKneePitch", ""}, {"right", "RKneePitch", ""}}, "t [s]", "I [A]");
    }
    return true;
  });
  for (std::size_t speed = 0; speed < std::size(kSpeeds); ++speed) {
    const EnergySpeed& sp = kSpeeds[speed];
    const auto& rep = repeats[speed];
    const double ours = mean_work(rep[0].total), base = mean_work(rep[1].total);
    auto lo = [](const std::vector<double>& v) {
      return v.empty() ? kNaN : *std::min_element(v.begin(), v.end());
    };
    auto hi = [](const std::vector<double>& v) {
      return v.empty() ? kNaN : *std::max_element(v.begin(), v.end());
    };
    figure.add_row({mean_work(rep[0].speed), mean_work(rep[0].left), lo(rep[0].left),
                    hi(rep[0].left), mean_work(rep[0].right), mean_work(rep[1].speed),
                    mean_work(rep[1].left), lo(rep[1].left), hi(rep[1].left),
                    mean_work(rep[1].right)});
    rows.push_back(
        {std::to_string(sp.cm), mean_std(rep[0].speed, 4), mean_std(rep[0].left, 1),
         mean_std(rep[0].right, 1), mean_std(rep[1].speed, 4), mean_std(rep[1].left, 1),
         mean_std(rep[1].right, 1), fixed(saving_percent(ours, base), 1),
         fixed(sp.thesis_speed_stretched, 4) + "+-" + fixed(sp.thesis_std_stretched, 4),
         fixed(sp.thesis_speed_conventional, 4) + "+-" + fixed(sp.thesis_std_conventional, 4),
         std::isfinite(sp.thesis_saving) ? fixed(sp.thesis_saving, 0) : "<0"});
  }
  out << "Knee energy, 20 s walks on flat ground, U = " << kNominalArmatureVoltage
      << " V, dt = control period, " << seeds << " seeds (Eqs. 4.16-4.17; thesis: 30 walks)\n";
  print_table(out,
              {"cm/s", "v stretched", "W_L [J]", "W_R [J]", "v conventional", "W_L [J]", "W_R [J]",
               "saving %", "thesis v (T4.4)", "thesis v (T4.5)", "thesis saving %"},
              rows);
  if (falls > 0) out << falls << " walk(s) fell and are left out of the means\n";
  if (files) {
    plot::write_csv(o.out_dir + "/energy_walks.csv", walks);
    write_plot(o, figure, "energy_fig4.14-15", "Knee energy in 20 s (mean and left min/max)",
               "speed_stretched",
               {{"left_stretched", "left, stretched-knee (Fig. 4.14)", "speed_stretched"},
                {"left_min_stretched", "left min, stretched", "speed_stretched"},
                {"left_max_stretched", "left max, stretched", "speed_stretched"},
                {"right_stretched", "right, stretched-knee", "speed_stretched"},
                {"left_conventional", "left, conventional (Fig. 4.15)", "speed_conventional"},
                {"left_min_conventional", "left min, conventional", "speed_conventional"},
                {"left_max_conventional", "left max, conventional", "speed_conventional"},
                {"right_conventional", "right, conventional", "speed_conventional"}},
               "average speed [m/s]", "energy [J]", "linespoints");
  }
  return falls > 0 ? 2 : 0;
}

}  // namespace stride::experiments
