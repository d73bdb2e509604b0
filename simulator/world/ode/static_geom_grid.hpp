#pragma once
// Broad phase for geoms that never move (ground tiles, boxes, ramps): a uniform x-y grid built
// once, queried with a moving geom's bounding box. ODE's hash space tests a geom against every
// static geom (thousands on an uneven floor); the grid visits only the nearby ones, in the static
// space's own order, so the contacts and hence the simulation stay bit-identical.
#include <array>
#include <cmath>
#include <vector>

#include <ode/ode.h>

namespace stride::sim {

using Aabb = std::array<dReal, 6>;  // ODE order: min x, max x, min y, max y, min z, max z

// ODE's disjointness test, comparison for comparison.
inline bool aabbs_overlap(const dReal* a, const dReal* b) {
  return !(a[0] > b[1] || a[1] < b[0] || a[2] > b[3] || a[3] < b[2] || a[4] > b[5] || a[5] < b[4]);
}

class StaticGeomGrid {
 public:
  // Indexes the geoms of `space` (none may move afterwards) in its list order.
  explicit StaticGeomGrid(dSpaceID space);
  // Indexes bare boxes, by their ranks in `boxes` (no geoms: for another engine's static shapes).
  explicit StaticGeomGrid(std::vector<Aabb> boxes);

  int size() const { return static_cast<int>(boxes_.size()); }
  // The static geoms whose boxes overlap `box`, in the space's list order.
  void overlapping(const dReal* box, std::vector<dGeomID>& out) const;
  // The ranks of the boxes overlapping `box`, ascending.
  void overlapping_ranks(const dReal* box, std::vector<int>& out) const;

 private:
  void index();
  bool cell_range(const dReal* box, int& x0, int& x1, int& y0, int& y1) const;

  std::vector<dGeomID> geoms_;  // list order
  std::vector<Aabb> boxes_;
  std::vector<int> everywhere_;  // unbounded or huge geoms: always candidates
  Aabb bounds_ = {INFINITY, -INFINITY, INFINITY, -INFINITY, INFINITY, -INFINITY};  // of the rest
  std::vector<std::vector<int>> cells_;  // geom ranks per cell, ascending
  double origin_x_ = 0, origin_y_ = 0, cell_ = 1;
  int nx_ = 0, ny_ = 0;
  mutable std::vector<int> scratch_, ranks_;
};

}  // namespace stride::sim
