// Skipping the plane test for geoms whose box is above the plane never drops a contact.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "simulator/world/ode/ode_context.hpp"
#include "simulator/world/ode/plane_cull.hpp"

namespace stride::sim {
namespace {

TEST(PlaneCull, NeverSkipsAGeomThatTouches) {
  ensure_ode_initialised();
  dSpaceID space = dSimpleSpaceCreate(nullptr);
  const double nx = 0.1, ny = -0.2, nz = 1.0, len = std::sqrt(nx * nx + ny * ny + nz * nz);
  dGeomID plane = dCreatePlane(space, nx / len, ny / len, nz / len, 0.02);  // tilted, raised
  dGeomID shapes[] = {dCreateBox(space, 0.16, 0.09, 0.02), dCreateSphere(space, 0.03),
                      dCreateCylinder(space, 0.02, 0.1)};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int skipped = 0, touching = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    dGeomID g = shapes[trial % 3];
    dGeomSetPosition(g, 0.3 * u(rng), 0.3 * u(rng), 0.02 + 0.1 * u(rng));
    dMatrix3 r;
    dRFromEulerAngles(r, 3 * u(rng), 3 * u(rng), 3 * u(rng));
    dGeomSetRotation(g, r);
    dContactGeom c[8];
    const int n = dCollide(g, plane, 8, c, sizeof(dContactGeom));
    touching += n > 0;
    if (above_plane(g, plane)) {
      ++skipped;
      ASSERT_EQ(n, 0) << "trial " << trial;
    }
    EXPECT_FALSE(above_plane(plane, g));  // only a plane culls
  }
  EXPECT_GT(skipped, 2000);  // both cases were exercised
  EXPECT_GT(touching, 2000);
  dSpaceDestroy(space);
}

}  // namespace
}  // namespace stride::sim
