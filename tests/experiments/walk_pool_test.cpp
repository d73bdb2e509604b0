// Walks run in worker processes come back in setup order, bit-identical to running them in this
// process; a walk's error arrives in its turn; the recording codec round-trips exactly.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "console/experiments/recording_codec.hpp"
#include "console/experiments/walk_pool.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {
namespace {

WalkSetup short_walk(std::uint64_t seed, const std::string& scene = "hip_medium") {
  WalkSetup s{std::string(STRIDE_SOURCE_DIR) + "/scenes/experiments/" + scene + ".xml", seed};
  s.parameters = {{"PatternWalk", "steps=6"}};
  s.settle_seconds = 0.05;
  return s;
}

std::vector<WalkRecording> run(const std::vector<WalkSetup>& setups, int jobs) {
  std::vector<WalkRecording> out;
  record_walks(setups, jobs, [&](std::size_t i, WalkRecording&& r) {
    EXPECT_EQ(i, out.size());
    out.push_back(std::move(r));
    return true;
  });
  return out;
}

void expect_identical(const WalkRecording& a, const WalkRecording& b) {
  EXPECT_EQ(a.trace.columns, b.trace.columns);
  ASSERT_EQ(a.trace.rows.size(), b.trace.rows.size());
  for (std::size_t k = 0; k < a.trace.rows.size(); ++k)
    for (std::size_t c = 0; c < a.trace.rows[k].size(); ++c) {
      const double x = a.trace.rows[k][c], y = b.trace.rows[k][c];
      if (std::isnan(x))
        EXPECT_TRUE(std::isnan(y));
      else
        ASSERT_EQ(x, y) << "row " << k << " column " << a.trace.columns[c];
    }
  EXPECT_EQ(a.metrics.steps, b.metrics.steps);
  EXPECT_EQ(a.metrics.true_distance, b.metrics.true_distance);
  EXPECT_EQ(a.metrics.fell, b.metrics.fell);
  EXPECT_EQ(a.walk_duration, b.walk_duration);
  EXPECT_EQ(a.walk_module, b.walk_module);
}

TEST(WalkPool, WorkersGiveTheSameRecordingsInSetupOrder) {
  const std::vector<WalkSetup> setups = {short_walk(1), short_walk(2), short_walk(3, "none_fast")};
  const auto here = run(setups, 1);
  const auto forked = run(setups, 2);
  ASSERT_EQ(here.size(), 3u);
  ASSERT_EQ(forked.size(), 3u);
  EXPECT_GT(here[0].trace.rows.size(), 100u);
  EXPECT_NE(here[0].metrics.true_distance, here[1].metrics.true_distance);  // seeds differ
  for (int i = 0; i < 3; ++i) expect_identical(here[i], forked[i]);
}

TEST(WalkPool, StopsWhenTheExperimentSaysSo) {
  const std::vector<WalkSetup> setups = {short_walk(1), short_walk(2), short_walk(3)};
  std::vector<std::size_t> used;
  record_walks(setups, 3, [&](std::size_t i, WalkRecording&&) {
    used.push_back(i);
    return i < 1;
  });
  EXPECT_EQ(used, (std::vector<std::size_t>{0, 1}));
}

TEST(WalkPool, AWalksErrorComesInItsTurn) {
  const std::vector<WalkSetup> setups = {short_walk(1), short_walk(2, "no_such_scene"),
                                         short_walk(3)};
  for (int jobs : {1, 2}) {
    std::vector<std::size_t> used;
    try {
      record_walks(setups, jobs, [&](std::size_t i, WalkRecording&&) {
        used.push_back(i);
        return true;
      });
      ADD_FAILURE() << "no error with " << jobs << " jobs";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("no_such_scene"), std::string::npos) << e.what();
    }
    EXPECT_EQ(used, (std::vector<std::size_t>{0})) << jobs << " jobs";
  }
}

TEST(RecordingCodec, RoundTripsExactlyAndRejectsTruncatedBytes) {
  WalkRecording r;
  r.trace.columns = {"t", "x"};
  r.trace.add_row({0.1, std::numeric_limits<double>::quiet_NaN()});
  r.trace.add_row({-0.0, 1e-300});
  r.metrics.steps = 7;
  r.metrics.true_distance = 1.25;
  r.metrics.fell = true;
  r.metrics.fell_at = 3.5;
  r.walk_duration = 15;
  r.period = 0.01;
  r.walk_module = "PatternWalk";
  const std::string bytes = encode_recording(r);
  expect_identical(r, decode_recording(bytes));
  EXPECT_EQ(decode_recording(bytes).metrics.fell_at, 3.5);
  for (std::size_t cut : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1})
    EXPECT_THROW(decode_recording(std::string_view(bytes).substr(0, cut)), Error) << cut;
  EXPECT_THROW(decode_recording(bytes + "x"), Error);
}

}  // namespace
}  // namespace stride::experiments
