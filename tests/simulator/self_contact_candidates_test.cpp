// The robots' self-collision pre-check lists only pairs that can ever touch, and it never says
// "no overlap" when ODE's own pass would create a contact, so skipping that pass is exact.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "simulator/world/ode/ode_context.hpp"
#include "simulator/world/ode/self_contact_candidates.hpp"

namespace stride::sim {
namespace {

class SelfContactCandidatesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_ode_initialised();
    world_ = dWorldCreate();
    space_ = dHashSpaceCreate(nullptr);
  }
  void TearDown() override {
    dSpaceDestroy(space_);
    dWorldDestroy(world_);
  }
  dBodyID body() { return dBodyCreate(world_); }
  dGeomID box_on(dBodyID b, double x, double y, double z) {
    dGeomID g = dCreateBox(space_, 0.1, 0.1, 0.1);
    dGeomSetBody(g, b);
    dBodySetPosition(b, x, y, z);
    return g;
  }
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
};

struct Count {
  int contacts = 0;
};

void count_contacts(void* data, dGeomID a, dGeomID b) {
  dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
  if (ba && bb && dAreConnectedExcluding(ba, bb, dJointTypeContact)) return;  // as the world does
  dContactGeom c[8];
  static_cast<Count*>(data)->contacts += dCollide(a, b, 8, c, sizeof(dContactGeom));
}

TEST_F(SelfContactCandidatesTest, PairsLeaveOutOneBodyAndJoinedBodies) {
  dBodyID a = body(), b = body(), c = body();
  dGeomID a1 = box_on(a, 0, 0, 0);
  dGeomID a2 = dCreateSphere(space_, 0.05);
  dGeomSetBody(a2, a);
  box_on(b, 0.05, 0, 0);
  box_on(c, 1, 0, 0);
  dJointID hinge = dJointCreateHinge(world_, nullptr);
  dJointAttach(hinge, a, b);
  SelfContactCandidates candidates;
  candidates.rebuild(space_);
  EXPECT_EQ(candidates.geom_count(), 4);
  EXPECT_EQ(candidates.pair_count(), 3u);  // a1-c, a2-c, b-c
  EXPECT_FALSE(candidates.any_overlap());  // a and b overlap, but a joint joins them
  dBodySetPosition(c, 0.12, 0, 0);         // c's box now overlaps b's
  EXPECT_TRUE(candidates.any_overlap());
  (void)a1;
}

TEST_F(SelfContactCandidatesTest, NoOverlapMeansOdeFindsNoContact) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  std::vector<dBodyID> bodies;
  for (int i = 0; i < 8; ++i) {
    bodies.push_back(body());
    box_on(bodies.back(), u(rng), u(rng), u(rng));
  }
  for (int i = 0; i + 1 < 8; i += 2) {  // four joined pairs
    dJointID j = dJointCreateBall(world_, nullptr);
    dJointAttach(j, bodies[i], bodies[i + 1]);
  }
  SelfContactCandidates candidates;
  candidates.rebuild(space_);
  ASSERT_EQ(candidates.pair_count(), 28u - 4u);
  int skipped = 0, checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    for (dBodyID b : bodies) dBodySetPosition(b, u(rng), u(rng), u(rng));
    Count count;
    dSpaceCollide(space_, &count, &count_contacts);
    if (!candidates.any_overlap()) {
      ++skipped;
      ASSERT_EQ(count.contacts, 0) << "trial " << trial;
    } else {
      ++checked;
    }
  }
  EXPECT_GT(skipped, 100);  // both branches were exercised
  EXPECT_GT(checked, 100);
}

}  // namespace
}  // namespace stride::sim
