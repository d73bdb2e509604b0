#pragma once
// Under the contact law, MuJoCo's box-box contacts are replaced by ODE's box-box collider's for
// the same pair of boxes at the same poses, so that both engines hold a sole on the uneven floor's
// tiles at the same points. MuJoCo 2.2.2's collider finds other points there (on the hip walk's
// tiles 2.06 points a tile under a loaded sole against ODE's 1.53, 6.4 a sole against 4.4), which
// turn and tip the feet differently; on flat ground (box-plane) both find the same corners.
#include <vector>

#include <mujoco/mujoco.h>
#include <ode/ode.h>

namespace stride::sim {

class OdeBoxBoxContacts {
 public:
  OdeBoxBoxContacts();
  ~OdeBoxBoxContacts();
  OdeBoxBoxContacts(const OdeBoxBoxContacts&) = delete;
  OdeBoxBoxContacts& operator=(const OdeBoxBoxContacts&) = delete;

  // After mj_collision: every box-box pair's contacts become ODE's (at most `max_per_pair`, the
  // ODE world's own cap), each keeping MuJoCo's parameters for the pair (friction, margin, dim).
  void replace(const mjModel* m, mjData* d, int max_per_pair);
  // ODE's contacts between box geoms g1 and g2 at their sizes and poses in (m, d), at most
  // `max_per_pair`, written into `out` (room for 64) as contacts like `pair` (MuJoCo's parameters
  // for the pair) at ODE's points; returns how many.
  int collide(const mjModel* m, const mjData* d, const mjContact& pair, int max_per_pair,
              mjContact* out);

 private:
  void place(dGeomID g, const mjModel* m, const mjData* d, int geom);

  dGeomID a_ = nullptr, b_ = nullptr;
  std::vector<mjContact> kept_;
};

}  // namespace stride::sim
