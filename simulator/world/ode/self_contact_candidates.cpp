#include "simulator/world/ode/self_contact_candidates.hpp"

#include "simulator/world/ode/static_geom_grid.hpp"

namespace stride::sim {

void SelfContactCandidates::rebuild(dSpaceID space) {
  const int n = dSpaceGetNumGeoms(space);
  geoms_.clear();
  pairs_.clear();
  for (int i = 0; i < n; ++i) geoms_.push_back(dSpaceGetGeom(space, i));
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      dBodyID a = dGeomGetBody(geoms_[i]);
      dBodyID b = dGeomGetBody(geoms_[j]);
      if (!a && !b) continue;
      // The near callback drops these before colliding; ODE skips geoms of one body.
      if (a == b || (a && b && dAreConnectedExcluding(a, b, dJointTypeContact))) continue;
      pairs_.emplace_back(i, j);
    }
  boxes_.assign(6 * geoms_.size(), 0);
}

bool SelfContactCandidates::any_overlap() {
  if (pairs_.empty()) return false;
  for (std::size_t g = 0; g < geoms_.size(); ++g) dGeomGetAABB(geoms_[g], &boxes_[6 * g]);
  for (const auto& [i, j] : pairs_)
    if (aabbs_overlap(&boxes_[6 * i], &boxes_[6 * j])) return true;
  return false;
}

}  // namespace stride::sim
