// The per-body law's split over a body's points: by depth, so the body's force does not jump when
// the collider finds a point more or less (a sole's corner reaching the floor as it rocks).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "simulator/world/contact_law.hpp"
#include "tests/simulator/sim_test_util.hpp"

namespace stride {
namespace {

sim::ContactLaw body_law() {
  sim::ContactLaw law;
  law.stiffness = 1e5;
  law.damping = 1000;
  law.per_body = true;
  return law;
}

TEST(ContactLawShare, LevelPointsShareAlikeAndASurfacePointTakesAlmostNothing) {
  const sim::ContactLaw law = body_law();
  const sim::LawBodyLoad level{4, 4 * 0.5e-3};
  EXPECT_NEAR(sim::law_point_share(law, 0.5e-3, level), 0.25, 1e-12);
  // Two corners 1 mm deep and two at the surface: the deep ones carry all but 0.2 % of the law.
  const sim::LawBodyLoad edge{4, 2e-3};
  const double deep = sim::law_point_share(law, 1e-3, edge);
  const double surface = sim::law_point_share(law, 0.0, edge);
  EXPECT_NEAR(2 * deep + 2 * surface, 1.0, 1e-12);
  EXPECT_LT(surface, 1e-3);
  EXPECT_NEAR(deep, 0.5, 1e-3);
  // A point that stands off the surface (negative depth) counts as at it.
  EXPECT_DOUBLE_EQ(sim::law_point_share(law, -1e-4, edge), surface);
}

TEST(ContactLawShare, OnePointOrAPerPointLawTakesTheWholeLaw) {
  sim::ContactLaw law = body_law();
  EXPECT_DOUBLE_EQ(sim::law_point_share(law, 1e-3, {1, 1e-3}), 1.0);
  law.per_body = false;
  EXPECT_DOUBLE_EQ(sim::law_point_share(law, 1e-3, {4, 2e-3}), 1.0);
  const sim::ContactSoftness whole = sim::law_point_softness(law, 1.0, 0.001);
  const sim::ContactSoftness half = sim::law_point_softness(law, 0.5, 0.001);
  EXPECT_DOUBLE_EQ(half.erp, whole.erp);  // a share scales spring and damper alike
  EXPECT_NEAR(half.cfm, 2 * whole.cfm, 1e-15);
}

// The block resting on its face is lifted at one edge (10.5 N up, more than the m g / 2 that
// tips it): it turns about the other edge, the lifted corners' depth runs out and the collider
// drops them. The total normal force on the block must change smoothly through that: a split by
// count doubled the remaining corners' spring at that step.
class ContactLawEdgeLift : public ::testing::TestWithParam<std::string> {};

TEST_P(ContactLawEdgeLift, TheBodysForceDoesNotJumpAsCornersLeaveTheFloor) {
  auto sim = test::scene_from_text(test::on_engine(
      R"(<scene><physics solver="exact" step="1ms"/><contact stiffness="2e4" damping="400"/>
      <robot name="b" urdf="block.urdf" xyz="0 0 0.019"/>
      <push robot="b" body="block" force="0 0 10.5" at="-0.05 0 0" start="0.5" duration="0.2"/>
      </scene>)",
      GetParam()));
  double last = 0, largest_jump = 0;
  int points_before = 0, points_after = 0;
  sim->run_for(0.51);  // settled, and the push has begun
  sim->run_for(0.15, [&] {
    double fz = 0;
    for (const sim::ContactRecord& c : sim->world().contacts()) fz += std::abs(c.force_on_a.z());
    const int points = static_cast<int>(sim->world().contacts().size());
    if (points_before == 0) points_before = points;
    if (last > 0) largest_jump = std::max(largest_jump, std::abs(fz - last));
    last = fz;
    points_after = points;
  });
  RecordProperty("largest_jump_N", std::to_string(largest_jump));
  ASSERT_EQ(points_before, 4);  // on its face
  ASSERT_EQ(points_after, 2);   // on one edge
  EXPECT_LT(largest_jump, 1.0);
}

INSTANTIATE_TEST_SUITE_P(Engines, ContactLawEdgeLift, ::testing::ValuesIn(test::engines()),
                         test::engine_name);

}  // namespace
}  // namespace stride
