// Eqs. 4.16-4.17 on known current series: the energy is U * sum(I) * dt in closed form, only the
// walking samples of a trace count, and the mean/std/saving follow the thesis' definitions.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "console/experiments/knee_energy.hpp"
#include "console/experiments/knee_energy_experiment.hpp"

namespace stride::experiments {
namespace {

TEST(KneeEnergy, ConstantCurrentOverTwentySecondsIsUTimesITimesT) {
  const std::vector<double> current(2000, 0.5);  // 2000 samples of 10 ms, as in Sec. 4.3.4.3
  EXPECT_NEAR(electrical_work(current, kNominalArmatureVoltage, 0.01), 21.6 * 0.5 * 20.0, 1e-9);
}

TEST(KneeEnergy, RampCurrentSumsInClosedForm) {
  std::vector<double> current;
  for (int j = 1; j <= 100; ++j) current.push_back(0.01 * j);  // sum = 0.01 * 100 * 101 / 2
  EXPECT_NEAR(electrical_work(current, 21.6, 0.012), 21.6 * 50.5 * 0.012, 1e-9);
  EXPECT_EQ(electrical_work({}, 21.6, 0.01), 0.0);
}

TEST(KneeEnergy, MeanStdAndSavingFollowTheThesisDefinitions) {
  const std::vector<double> w{1, 2, 3, 4};
  EXPECT_DOUBLE_EQ(mean_work(w), 2.5);                   // Eq. 4.17
  EXPECT_DOUBLE_EQ(population_std(w), std::sqrt(1.25));  // 1/N, footnote 4
  EXPECT_DOUBLE_EQ(saving_percent(85, 100), 15.0);
  EXPECT_LT(saving_percent(110, 100), 0.0);
}

// A logged trace: 1 s standing, 20 s walking, 0.5 s after; only the walk's samples are summed.
TEST(KneeEnergy, OnlyTheWalkingSamplesOfALoggedTraceCount) {
  WalkRecording r;
  r.trace.columns = trace_columns();
  r.period = 0.01;
  r.walk_duration = 20.0;
  double sum_left = 0, sum_right = 0;
  for (int k = -100; k < 2050; ++k) {
    std::vector<double> row(static_cast<std::size_t>(Trace::count), 0.0);
    const double tp = k * r.period;
    row[col(Trace::pattern_t)] = tp;
    row[col(Trace::knee_current_l)] = 0.3 + 0.2 * std::sin(0.01 * k);
    row[col(Trace::knee_current_r)] = 1.0 + 1e-3 * k;
    if (k >= 0 && k < 2000) {
      sum_left += row[col(Trace::knee_current_l)];
      sum_right += row[col(Trace::knee_current_r)];
    }
    r.trace.add_row(std::move(row));
  }
  const KneeEnergy e = knee_energy(r);
  EXPECT_EQ(e.samples, 2000);
  EXPECT_NEAR(e.left, 21.6 * sum_left * 0.01, 1e-9);
  EXPECT_NEAR(e.right, 21.6 * sum_right * 0.01, 1e-9);
  EXPECT_NEAR(e.right, 21.6 * 0.01 * (2000 + 1e-3 * 1999 * 2000 / 2), 1e-9);
}

}  // namespace
}  // namespace stride::experiments
