#pragma once
// A cheap pre-check for the robots' own collision pass. ODE's hash space re-hashes every robot
// geom each step (about 8 % of a standing NAO's step) although the pairs that can ever give a
// contact are fixed: geoms of two different bodies that no joint connects. When no such pair's
// boxes overlap, the pass would create no contact, so it can be skipped; otherwise ODE runs as
// before, in its own order, and the simulation stays bit-identical.
#include <utility>
#include <vector>

#include <ode/ode.h>

namespace stride::sim {

class SelfContactCandidates {
 public:
  // Lists the candidate pairs of `space` (robot geoms; call again when geoms were added).
  void rebuild(dSpaceID space);
  int geom_count() const { return static_cast<int>(geoms_.size()); }
  std::size_t pair_count() const { return pairs_.size(); }
  // True when some candidate pair's bounding boxes overlap (ODE's own boxes and test).
  bool any_overlap();

 private:
  std::vector<dGeomID> geoms_;
  std::vector<std::pair<int, int>> pairs_;  // indices into geoms_
  std::vector<dReal> boxes_;                // 6 per geom, refreshed by any_overlap()
};

}  // namespace stride::sim
