// <seeds heading_spread position_spread>: a study's seeds as perturbed starts (issue 33, item 3).
// Run with seed s starts as `stride run --ensemble`'s member of seed s: the same heading and x/y
// offsets, so a sweep's spread is over nearby starts, not only over sensor noise (with the exact
// solver an uncontrolled walk is otherwise the same walk under every seed).
#include <string>

#include <gtest/gtest.h>

#include "console/sweep/run_session.hpp"
#include "console/sweep/sweep.hpp"
#include "console/sweep/sweep_parser.hpp"
#include "console/sweep/tally.hpp"
#include "robot/core/error.hpp"
#include "simulator/scene/scene_parser.hpp"
#include "simulator/scene/start_perturbation.hpp"

namespace stride::sweep {
namespace {

const std::string kDir = std::string(STRIDE_SOURCE_DIR) + "/tests/sweep/";

SweepSpec spec_with(const std::string& seeds_attributes) {
  return parse_sweep_text(R"(<sweep name="starts" scenes="../../scenes">
  <scene file="nao_stand.xml"/>
  <seeds from="1" to="3" )" + seeds_attributes +
                              R"(/>
  <run seconds="0.01"/>
  <record><value name="t" key="sim.time"/></record>
</sweep>)",
                          kDir + "starts.sweep.xml");
}

TEST(PerturbedStarts, SeedStartsAsTheEnsembleMemberOfThatSeed) {
  const Sweep sweep(spec_with(R"(heading_spread="0.003" position_spread="2mm")"), false);
  EXPECT_DOUBLE_EQ(sweep.spec().start_heading_spread, 0.003);
  EXPECT_DOUBLE_EQ(sweep.spec().start_position_spread, 0.002);
  const sim::RobotPlacement base =
      sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/scenes/nao_stand.xml").robots[0];
  ASSERT_EQ(sweep.plan().runs.size(), 3u);
  double last_heading = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    SCOPED_TRACE(seed);
    const auto session = build_run_session(sweep.spec(), sweep.plan().runs[seed - 1]);
    const sim::SceneDescription& scene = session->simulation().scene();
    const sim::StartPerturbation want = sim::ensemble_member({1, seed, 0.003, 0.002}, 0);
    EXPECT_EQ(scene.physics.seed, seed);
    const sim::RobotPlacement& r = scene.robots[0];
    EXPECT_DOUBLE_EQ(r.rpy.z(), base.rpy.z() + want.heading);
    EXPECT_DOUBLE_EQ(r.xyz.x(), base.xyz.x() + want.offset.x());
    EXPECT_DOUBLE_EQ(r.xyz.y(), base.xyz.y() + want.offset.y());
    EXPECT_LE(std::abs(want.heading), 0.003);
    EXPECT_NE(want.heading, last_heading);  // each seed its own start
    last_heading = want.heading;
  }
}

TEST(PerturbedStarts, WithoutSpreadsSeedsChangeOnlyTheSeed) {
  const Sweep sweep(spec_with(""), false);
  const sim::RobotPlacement base =
      sim::parse_scene_file(std::string(STRIDE_SOURCE_DIR) + "/scenes/nao_stand.xml").robots[0];
  const auto session = build_run_session(sweep.spec(), sweep.plan().runs[2]);
  EXPECT_EQ(session->simulation().scene().physics.seed, 3u);
  EXPECT_EQ(session->simulation().scene().robots[0].rpy, base.rpy);
  EXPECT_EQ(session->simulation().scene().robots[0].xyz, base.xyz);
}

TEST(PerturbedStarts, SpreadOutOfRangeIsAnErrorAtFileLine) {
  try {
    spec_with(R"(heading_spread="1")");
    ADD_FAILURE() << "accepted a 1 rad heading spread";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("starts.sweep.xml:3"), std::string::npos) << what;
    EXPECT_NE(what.find("heading_spread"), std::string::npos) << what;
  }
}

// A mean with its sd over a group whose every walk the `where` leaves out prints "-" alone.
TEST(SpreadColumns, EmptyMeanPrintsOneDash) {
  const Sweep sweep(parse_sweep_text(R"(<sweep name="starts" scenes="../../scenes">
  <scene file="nao_stand.xml"/>
  <seeds from="1" to="2"/>
  <run seconds="0.01"/>
  <record><value name="fell" key="walk.fell"/><value name="t" key="sim.time"/></record>
  <tally name="all" by="seed"><mean name="t" of="t" where="not fell" sd="true"/></tally>
</sweep>)",
                                     kDir + "starts.sweep.xml"),
                    false);
  const std::vector<std::string> header = sweep.csv_header();
  const auto row = [&](const std::string& seed, const std::string& fell) {
    std::vector<std::string> r(header.size(), "");
    for (std::size_t i = 0; i < header.size(); ++i) {
      if (header[i] == "seed") r[i] = seed;
      if (header[i] == "status") r[i] = "ok";
      if (header[i] == "fell") r[i] = fell;
      if (header[i] == "t") r[i] = "0.25";
    }
    return r;
  };
  const auto tables = Tallies(sweep).compute({row("1", "0"), row("2", "1")});
  ASSERT_EQ(tables.size(), 1u);
  ASSERT_EQ(tables[0].texts.size(), 2u);
  EXPECT_EQ(tables[0].texts[0].back(), "0.25+-0");
  EXPECT_EQ(tables[0].texts[1].back(), "-");
}

}  // namespace
}  // namespace stride::sweep
