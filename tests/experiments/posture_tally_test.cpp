// The posture experiment's per-case count against hand-made walks: a fall and a tilt past
// kTipAngle are both lost, the first way of each is counted, kept walks give the mean true and
// FK distance and the largest |pitch|, next to the thesis' figure.
#include <cmath>

#include <gtest/gtest.h>

#include "console/experiments/posture_tally.hpp"

namespace stride::experiments {
namespace {

WalkSummary walk(double distance, double pitch_min, double pitch_max, bool fell, sim::Tip tip) {
  WalkSummary s;
  s.distance = distance;
  s.fk_distance = 1.25 * distance;  // feet that slip back make FK overstate the advance
  s.pitch_min = pitch_min;
  s.pitch_max = pitch_max;
  s.fell = fell;
  s.tipped = tip;
  s.tipped_at = tip == sim::Tip::None ? -1 : 5;
  return s;
}

TEST(PostureTally, CountsLostWalksByWayAndAveragesTheKeptOnes) {
  PostureTally t;
  add_walk(t, walk(2.0, -0.10, 0.05, false, sim::Tip::None));
  add_walk(t, walk(1.0, -0.05, 0.20, false, sim::Tip::None));
  add_walk(t, walk(0.5, -1.50, 0.10, true, sim::Tip::Backward));
  add_walk(t, walk(0.7, -0.10, 0.45, false, sim::Tip::Forward));  // tilted, did not fall
  add_walk(t, walk(0.9, -0.10, 0.10, true, sim::Tip::Left));
  EXPECT_EQ(t.walks, 5);
  EXPECT_EQ(t.fell, 2);
  EXPECT_EQ(t.tipped(), 3);
  EXPECT_EQ(t.lost(), 3);
  EXPECT_EQ(t.kept, 2);
  EXPECT_EQ(t.tip_way, (std::array<int, 4>{1, 1, 0, 1}));
  const auto row = tally_row("none_fast", t, 3.5469);
  ASSERT_EQ(row.size(), tally_header().size());
  EXPECT_EQ(row[4], "3/5");
  EXPECT_EQ(row[5], "1/1/0/1");
  EXPECT_EQ(row[7], "1.500");   // (2.0 + 1.0) / 2
  EXPECT_EQ(row[8], "1.875");   // (2.5 + 1.25) / 2
  EXPECT_EQ(row[9], "3.547");   // the printed figure, rounded like ours
  EXPECT_EQ(row[10], "0.200");  // the largest |pitch| of the two kept walks
}

TEST(PostureTally, NoKeptWalkLeavesTheirColumnsEmpty) {
  PostureTally t;
  add_walk(t, walk(0.1, -1.5, 0.0, true, sim::Tip::Backward));
  const auto row = tally_row("none_slow", t, std::nan(""));  // the none cases print no figure
  EXPECT_EQ(row[4], "1/1");
  EXPECT_EQ(row[7], "-");
  EXPECT_EQ(row[8], "-");
  EXPECT_EQ(row[9], "-");
  EXPECT_EQ(row[10], "-");
}

}  // namespace
}  // namespace stride::experiments
