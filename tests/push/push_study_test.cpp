// The Ch. 7 push study as a sweep (scenes/experiments/push.sweep.xml) measures what the
// hand-written `stride push-sweep` loop measures: for the same pushes the engine's rows hold the
// same estimated CoM state at the push's end + 30 ms, the same predicted recovery (BalanceOutlook
// against balance::classify) and the same observed outcome.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "console/cli/subcommand.hpp"
#include "console/sweep/sweep_engine.hpp"
#include "console/sweep/sweep_parser.hpp"

namespace stride::cli {
int push_sweep_main(Args args, std::ostream& out, std::ostream& err);
}

namespace stride::sweep {
namespace {

std::size_t column(const Sweep& s, const std::string& name) {
  const auto h = s.csv_header();
  return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
}

TEST(PushStudy, TheSweepMeasuresWhatPushSweepMeasures) {
  const std::string dir = std::string(STRIDE_SOURCE_DIR) + "/scenes/";
  const Sweep s(parse_sweep_file(dir + "experiments/push.sweep.xml"));
  SweepOptions o;
  o.print_tallies = false;
  o.only = {{"strategy", {"ankle"}}, {"impulse", {"2", "-2"}}};
  std::ostringstream text;
  const SweepResult r = run_sweep(s, Tallies(s), *in_process_executor(), o, text);
  ASSERT_TRUE(r.complete);
  ASSERT_EQ(r.rows.size(), 2u);  // in plan order: -2 (backward), then 2 (forward)

  std::ostringstream out, err;
  const std::vector<std::string> args = {"--scene",      dir + "push/stand_balance.xml",
                                         "--strategy",   "ankle",
                                         "--impulses",   "2",
                                         "--directions", "180,0"};
  ASSERT_EQ(cli::push_sweep_main(args, out, err), 0) << err.str();
  std::istringstream lines(out.str());
  std::string line;
  std::getline(lines, line), std::getline(lines, line);  // title, header
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& row = r.rows[k];
    SCOPED_TRACE("impulse " + row[column(s, "impulse")]);
    ASSERT_TRUE(std::getline(lines, line));
    std::istringstream p(line);
    double impulse, direction, x, v, x_true, v_true;
    std::string predicted, predicted_true, expected, observed, agree;
    ASSERT_TRUE(p >> impulse >> direction >> x >> v >> x_true >> v_true >> predicted >>
                predicted_true >> expected >> observed >> agree)
        << line;
    EXPECT_EQ(row[column(s, "status")], "ok") << row.back();
    EXPECT_NEAR(std::stod(row[column(s, "x_est")]), x, 0.6e-4);  // printed with 4 decimals
    EXPECT_NEAR(std::stod(row[column(s, "v_est")]), v, 0.6e-4);
    EXPECT_EQ(row[column(s, "expected")] == "1", expected == "recover");
    EXPECT_EQ(row[column(s, "recovered")] == "1", observed == "recovered");
    EXPECT_EQ(row[column(s, "agree")] == "1", agree == "yes");
    // The push moved the CoM its way.
    EXPECT_GT(std::stod(row[column(s, "v_est")]) * std::stod(row[column(s, "impulse")]), 0.1);
  }
}

}  // namespace
}  // namespace stride::sweep
