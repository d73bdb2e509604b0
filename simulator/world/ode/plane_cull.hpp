#pragma once
// A robot geom high above the ground cannot touch it: ODE's plane test for each of them, every
// step, can be skipped when the geom's bounding box lies wholly on the plane's free side.
#include <ode/ode.h>

namespace stride::sim {

// True when `plane` is a plane and `g`'s box lies wholly on its free side (ODE's plane test
// would find no contact).
inline bool above_plane(dGeomID g, dGeomID plane) {
  if (dGeomGetClass(plane) != dPlaneClass || dGeomGetClass(g) == dPlaneClass) return false;
  dVector4 p;  // n . x = d
  dGeomPlaneGetParams(plane, p);
  dReal box[6];
  dGeomGetAABB(g, box);
  dReal lowest = 0;  // n . x at the box corner furthest against the normal
  for (int k = 0; k < 3; ++k) lowest += p[k] * (p[k] > 0 ? box[2 * k] : box[2 * k + 1]);
  return lowest > p[3];
}

}  // namespace stride::sim
