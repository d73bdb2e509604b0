#include "console/experiments/kalman_experiment.hpp"

#include <ostream>
#include <string>

#include "console/experiments/figure_index.hpp"
#include "console/experiments/kalman_study.hpp"
#include "console/experiments/parameter_overrides.hpp"
#include "console/experiments/walk_recording.hpp"

namespace stride::experiments {
namespace {

struct Setting {
  std::string figure;
  Eigen::Vector4d q, r;
};

std::string diag(const Eigen::Vector4d& v) {
  std::string s = "[";
  for (int i = 0; i < 4; ++i) {
    char b[16];
    std::snprintf(b, sizeof b, "%s%.0e", i ? " " : "", v[i]);
    s += b;
  }
  return s + "]";
}

// Figs. 4.1 and 4.2 go into one family folder of the output.
const std::string kKalmanFigures = "figures/kalman_pitch_estimates";

std::vector<Eigen::Vector2d> angles(const std::vector<Eigen::Vector4d>& x) {
  std::vector<Eigen::Vector2d> a;
  for (const auto& v : x) a.push_back(v.head<2>());
  return a;
}

std::vector<Eigen::Vector2d> rates(const std::vector<Eigen::Vector4d>& x) {
  std::vector<Eigen::Vector2d> a;
  for (const auto& v : x) a.push_back(v.tail<2>());
  return a;
}

// The walk, its replayable series and what the angle table filtered (reused by the rates and
// the figures).
struct KalmanRun {
  WalkRecording rec;
  KalmanSeries series;
  std::size_t first = 0;  // samples from here on are scored (after L's transient)
  std::vector<Setting> settings;
  std::vector<std::vector<Eigen::Vector4d>> estimates;  // one per setting
};

const Eigen::Vector4d kQThesis(1e-1, 1e-1, 1e-5, 1e-5), kRThesis(1e-4, 1e-4, 1e-3, 1e-3);

KalmanRun record_kalman_walk(const ExperimentOptions& o) {
  // Table 4.2's walk (the thesis' Q/R tuning runs), hip strategy of Fig. 4.7, uneven floor;
  // its 32 mm step height together with A_l = 5 mm makes the simulated NAO fall, so the step
  // height stays at Table 4.3's 26 mm.
  WalkSetup setup{scene_path(o, "hip_medium"), 1};
  setup.parameters = {{"PatternWalk", "z_min=0.321 z_max=0.323 A_l=0.005"}};
  KalmanRun k;
  k.rec = record_walk(with_overrides(o, setup));
  k.series = kalman_series(k.rec);
  k.first = static_cast<std::size_t>(1.0 / k.rec.period);
  return k;
}

void print_walk_header(const KalmanRun& k, std::ostream& out) {
  std::vector<double> gyro_pitch, true_pitch_rate, gyro_roll, true_roll_rate;
  for (const console::WalkFrame& f : k.rec.frames) {
    gyro_pitch.push_back(f.gyro_pitch);
    gyro_roll.push_back(f.gyro_roll);
    true_pitch_rate.push_back(f.true_pitch_rate);
    true_roll_rate.push_back(f.true_roll_rate);
  }
  const WalkSummary walk = summarize(k.rec);
  out << "Torso state during the Table 4.2 walk (hip strategy, uneven floor), against ground "
         "truth; "
      << k.rec.frames.size() << " frames; walk " << fixed(walk.speed, 4) << " m/s, "
      << (walk.fell ? "FELL (scores are over the fall too)" : "did not fall") << "\n";
  out << "gyro vs d/dt(true angle) correlation: pitch "
      << fixed(correlation(gyro_pitch, true_pitch_rate), 3) << ", roll "
      << fixed(correlation(gyro_roll, true_roll_rate), 3)
      << " (+1: the gyro sign matches the filter's model, Eq. 4.6)\n";
}

// Figs. 4.1-4.2: the angles rerun offline with other Q and R, scored beside the IMU and the
// module's own online estimate.
void angle_table(KalmanRun& k, std::ostream& out) {
  std::vector<Eigen::Vector2d> online, imu;
  for (const console::WalkFrame& f : k.rec.frames) {
    online.push_back({f.est_pitch, f.est_roll});
    imu.push_back({f.imu_pitch, f.imu_roll});
  }
  std::vector<std::vector<std::string>> rows;
  auto add = [&](const std::string& what, const std::string& q, const std::string& r,
                 const std::vector<Eigen::Vector2d>& estimate) {
    const EstimateScore s = score_estimate(estimate, k.series.truth, k.rec.period, k.first);
    rows.push_back({what, q, r, fixed(s.rms_pitch * 1e3, 2), fixed(s.rms_roll * 1e3, 2),
                    fixed(s.lag_pitch * 1e3, 0), fixed(s.lag_roll * 1e3, 0)});
  };
  add("IMU angles (raw)", "-", "-", imu);
  add("TorsoStateEstimator online", "module", "module", online);
  for (double qa : {1e-5, 1e-3, 1e-1, 1e1})  // Fig. 4.1: R fixed
    k.settings.push_back({"Fig. 4.1", {qa, qa, 1e-5, 1e-5}, Eigen::Vector4d::Constant(1e-3)});
  for (double ra : {1e-1, 1e-2, 1e-3, 1e-4})  // Fig. 4.2: Q fixed
    k.settings.push_back({"Fig. 4.2", kQThesis, {ra, ra, 1e-3, 1e-3}});
  k.settings.push_back({"chosen (Sec. 4.3.2)", kQThesis, kRThesis});
  for (const Setting& s : k.settings) {
    k.estimates.push_back(filter_series(k.series, s.q, s.r, 1000));
    add(s.figure, diag(s.q), diag(s.r), angles(k.estimates.back()));
  }
  out << "Q/R rerun offline on the same IMU data (P0 = 1000 I); errors after the first 1 s\n";
  print_table(out,
              {"estimate", "Q diag", "R diag", "RMS pitch [mrad]", "RMS roll [mrad]",
               "lag pitch [ms]", "lag roll [ms]"},
              rows);
}

// The rates the D terms of Eq. 4.8 and Eq. 4.9 act on, with the gyro offset started either way.
void rate_table(const KalmanRun& k, std::ostream& out) {
  std::vector<Eigen::Vector2d> online_rate;
  for (const console::WalkFrame& f : k.rec.frames)
    online_rate.push_back({f.est_pitch_rate, f.est_roll_rate});
  std::vector<std::vector<std::string>> rate_rows;
  auto add_rate = [&](const std::string& what, const std::vector<Eigen::Vector2d>& estimate) {
    const EstimateScore s = score_estimate(estimate, k.series.truth_rate, k.rec.period, k.first);
    rate_rows.push_back({what, fixed(s.rms_pitch * 1e3, 1), fixed(s.rms_roll * 1e3, 1),
                         fixed(s.lag_pitch * 1e3, 0), fixed(s.lag_roll * 1e3, 0)});
  };
  add_rate("calibrated gyro, C from its first sample", rates(k.series.y));
  add_rate("calibrated gyro, C from 0", rates(kalman_series(k.rec, 0.001, false).y));
  add_rate("TorsoStateEstimator online", online_rate);
  // Q's rate entries decide how far the filtered rates trail the gyro (the D terms' delay).
  for (double qr : {1e-6, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 1e-2}) {
    const Eigen::Vector4d q(kQThesis[0], kQThesis[1], qr, qr);
    if (q == kQThesis)  // already filtered above, as the chosen setting
      add_rate("offline, Q " + diag(q) + " (chosen)", rates(k.estimates.back()));
    else
      add_rate("offline, Q " + diag(q), rates(filter_series(k.series, q, kRThesis, 1000)));
  }
  out << "Torso rates against ground truth, errors after the first 1 s (offline rows: R "
      << diag(kRThesis) << ")\n";
  print_table(out,
              {"estimate", "RMS pitch rate [mrad/s]", "RMS roll rate [mrad/s]", "lag pitch [ms]",
               "lag roll [ms]"},
              rate_rows);
}

void write_figures(const ExperimentOptions& o, const KalmanRun& k, std::ostream& out) {
  plot::Table fig{{"t", "true_pitch", "imu_pitch"}};
  for (std::size_t i = 0; i < k.settings.size(); ++i)
    fig.columns.push_back("pitch_" + std::to_string(i + 1));
  for (std::size_t i = 0; i < k.series.y.size(); ++i) {
    std::vector<double> row{k.rec.frames[i].t, k.series.truth[i][0], k.series.y[i][0]};
    for (const auto& e : k.estimates) row.push_back(e[i][0]);
    fig.add_row(std::move(row));
  }
  // The estimates first, the IMU and the ground truth last: the true curve is drawn on top.
  auto series_of = [&](std::size_t from, std::size_t to) {
    std::vector<plot::Series> s;
    for (std::size_t i = from; i < to; ++i)
      s.push_back({"pitch_" + std::to_string(i + 1),
                   "Q " + diag(k.settings[i].q) + " R " + diag(k.settings[i].r), ""});
    s.push_back({"imu_pitch", "IMU angle", ""});
    s.push_back({"true_pitch", "ground truth", ""});
    return s;
  };
  make_figure_dir(o, kKalmanFigures);
  write_plot(o, fig, kKalmanFigures + "/fig4.1_q",
             "Torso pitch estimates, R fixed (Fig. 4.1), ground truth on top", "t", series_of(0, 4),
             "t [s]", "pitch [rad]");
  write_plot(o, fig, kKalmanFigures + "/fig4.2_r",
             "Torso pitch estimates, Q fixed (Fig. 4.2), ground truth on top", "t", series_of(4, 8),
             "t [s]", "pitch [rad]");
  plot::write_csv(o.out_dir + "/kalman_walk_trace.csv", trace_table(k.rec));
  if (o.plots) print_figure_index(o.out_dir, "kalman", out);
}

}  // namespace

int run_kalman_experiment(const ExperimentOptions& o, std::ostream& out) {
  const bool files = prepare_out_dir(o);
  KalmanRun k = record_kalman_walk(o);
  print_walk_header(k, out);
  angle_table(k, out);
  rate_table(k, out);
  if (files) write_figures(o, k, out);
  return 0;
}

}  // namespace stride::experiments
