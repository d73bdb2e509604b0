// The static-geometry broad phase finds exactly the geoms ODE's exhaustive test finds, in the same
// order, so replacing it cannot change a contact.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "simulator/world/ode/ode_context.hpp"
#include "simulator/world/ode/static_geom_grid.hpp"

namespace stride::sim {
namespace {

std::vector<dGeomID> exhaustive(dSpaceID space, const dReal* box) {
  std::vector<dGeomID> out;
  for (int i = 0; i < dSpaceGetNumGeoms(space); ++i) {
    dGeomID g = dSpaceGetGeom(space, i);
    dReal b[6];
    dGeomGetAABB(g, b);
    if (aabbs_overlap(b, box)) out.push_back(g);
  }
  return out;
}

class StaticGeomGridTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ensure_ode_initialised();
    space_ = dSimpleSpaceCreate(nullptr);
  }
  void TearDown() override { dSpaceDestroy(space_); }
  dSpaceID space_ = nullptr;
};

TEST_F(StaticGeomGridTest, MatchesTheExhaustiveTestInSpaceOrder) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  dCreatePlane(space_, 0, 0, 1, 0);                   // unbounded: a candidate everywhere
  dGeomID ramp = dCreateBox(space_, 3.0, 1.0, 0.05);  // spans many cells
  dGeomSetPosition(ramp, -1.5, 0, 0.1);
  dMatrix3 r;
  dRFromEulerAngles(r, 0, 0.17, 0);
  dGeomSetRotation(ramp, r);
  for (int i = 0; i < 40; ++i)  // a tiled floor with tilted tiles
    for (int j = 0; j < 12; ++j) {
      dGeomID t = dCreateBox(space_, 0.05, 0.05, 0.02);
      dGeomSetPosition(t, 0.1 + 0.05 * i, -0.3 + 0.05 * j, -0.01 + 0.003 * u(rng));
      dRFromEulerAngles(r, 0.02 * (u(rng) - 0.5), 0.02 * (u(rng) - 0.5), 0);
      dGeomSetRotation(t, r);
    }
  const StaticGeomGrid grid(space_);
  ASSERT_EQ(grid.size(), 2 + 40 * 12);
  std::vector<dGeomID> found;
  int nonempty = 0;
  for (int q = 0; q < 2000; ++q) {
    const double x = -3.5 + 6.5 * u(rng), y = -0.8 + 1.6 * u(rng), z = -0.03 + 0.1 * u(rng);
    const double hx = 0.2 * u(rng), hy = 0.2 * u(rng), hz = 0.1 * u(rng);
    const dReal box[6] = {x - hx, x + hx, y - hy, y + hy, z - hz, z + hz};
    grid.overlapping(box, found);
    ASSERT_EQ(found, exhaustive(space_, box)) << "query " << q;
    nonempty += found.size() > 2;
  }
  RecordProperty("queries_with_tiles", nonempty);
  EXPECT_GT(nonempty, 150);  // the queries do hit tiles, not only the plane and the ramp
}

TEST_F(StaticGeomGridTest, EmptyAndUnboundedSpacesReturnOnlyTheUnbounded) {
  const dReal box[6] = {0, 1, 0, 1, -1, 1};
  std::vector<dGeomID> found;
  StaticGeomGrid(space_).overlapping(box, found);
  EXPECT_TRUE(found.empty());
  dGeomID plane = dCreatePlane(space_, 0, 0, 1, 0);
  StaticGeomGrid(space_).overlapping(box, found);
  EXPECT_EQ(found, std::vector<dGeomID>{plane});
  const dReal above[6] = {0, 1, 0, 1, 0.5, 1};  // an axis-aligned plane's box ends at its surface
  StaticGeomGrid(space_).overlapping(above, found);
  EXPECT_EQ(found, exhaustive(space_, above));
}

}  // namespace
}  // namespace stride::sim
