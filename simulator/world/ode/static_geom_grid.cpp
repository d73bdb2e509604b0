#include "simulator/world/ode/static_geom_grid.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace stride::sim {
namespace {
constexpr int kMaxCellsPerAxis = 512;
constexpr int kMaxCellsPerGeom = 64;  // larger geoms are tested against everything
}  // namespace

StaticGeomGrid::StaticGeomGrid(dSpaceID space) {
  const int n = dSpaceGetNumGeoms(space);
  for (int i = 0; i < n; ++i) {
    dGeomID g = dSpaceGetGeom(space, i);
    Aabb b;
    dGeomGetAABB(g, b.data());
    geoms_.push_back(g);
    boxes_.push_back(b);
  }
  index();
}

StaticGeomGrid::StaticGeomGrid(std::vector<Aabb> boxes) : boxes_(std::move(boxes)) {
  index();
}

void StaticGeomGrid::index() {
  const int n = size();
  double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
  double smallest = INFINITY;
  std::vector<bool> bounded(n);
  for (int i = 0; i < n; ++i) {
    const Aabb& b = boxes_[i];
    bounded[i] =
        std::isfinite(b[0]) && std::isfinite(b[1]) && std::isfinite(b[2]) && std::isfinite(b[3]);
    if (!bounded[i]) continue;
    min_x = std::min(min_x, double(b[0]));
    max_x = std::max(max_x, double(b[1]));
    min_y = std::min(min_y, double(b[2]));
    max_y = std::max(max_y, double(b[3]));
    smallest = std::min(smallest, std::max(double(b[1] - b[0]), double(b[3] - b[2])));
    for (int k = 0; k < 6; k += 2) {
      bounds_[k] = std::min(bounds_[k], b[k]);
      bounds_[k + 1] = std::max(bounds_[k + 1], b[k + 1]);
    }
  }
  if (std::isfinite(min_x)) {
    // Cells about twice the smallest geom, but never more than kMaxCellsPerAxis a side.
    const double extent = std::max(max_x - min_x, max_y - min_y);
    cell_ = std::max({2 * smallest, extent / kMaxCellsPerAxis, 1e-3});
    origin_x_ = min_x;
    origin_y_ = min_y;
    nx_ = static_cast<int>((max_x - min_x) / cell_) + 1;
    ny_ = static_cast<int>((max_y - min_y) / cell_) + 1;
    cells_.resize(static_cast<size_t>(nx_) * ny_);
  }
  for (int i = 0; i < n; ++i) {
    int x0, x1, y0, y1;
    if (!bounded[i] || !cell_range(boxes_[i].data(), x0, x1, y0, y1) ||
        (x1 - x0 + 1) * (y1 - y0 + 1) > kMaxCellsPerGeom) {
      everywhere_.push_back(i);
      continue;
    }
    for (int x = x0; x <= x1; ++x)
      for (int y = y0; y <= y1; ++y) cells_[static_cast<size_t>(x) * ny_ + y].push_back(i);
  }
}

bool StaticGeomGrid::cell_range(const dReal* box, int& x0, int& x1, int& y0, int& y1) const {
  if (nx_ == 0) return false;
  const auto clamp_cell = [](double v, int n) {
    return static_cast<int>(std::clamp(std::floor(v), 0.0, double(n - 1)));
  };
  const double ax = (box[0] - origin_x_) / cell_, bx = (box[1] - origin_x_) / cell_;
  const double ay = (box[2] - origin_y_) / cell_, by = (box[3] - origin_y_) / cell_;
  if (!(bx >= 0 && ax < nx_ && by >= 0 && ay < ny_)) return false;  // also rejects NaN
  x0 = clamp_cell(ax, nx_);
  x1 = clamp_cell(bx, nx_);
  y0 = clamp_cell(ay, ny_);
  y1 = clamp_cell(by, ny_);
  return true;
}

void StaticGeomGrid::overlapping(const dReal* box, std::vector<dGeomID>& out) const {
  out.clear();
  overlapping_ranks(box, ranks_);
  for (int i : ranks_) out.push_back(geoms_[i]);
}

void StaticGeomGrid::overlapping_ranks(const dReal* box, std::vector<int>& out) const {
  out.clear();
  // A robot's upper body is far above a floor's tiles: nothing to visit.
  if (everywhere_.empty() && !aabbs_overlap(bounds_.data(), box)) return;
  scratch_.assign(everywhere_.begin(), everywhere_.end());
  int x0, x1, y0, y1;
  if (cell_range(box, x0, x1, y0, y1))
    for (int x = x0; x <= x1; ++x)
      for (int y = y0; y <= y1; ++y) {
        const auto& c = cells_[static_cast<size_t>(x) * ny_ + y];
        scratch_.insert(scratch_.end(), c.begin(), c.end());
      }
  std::sort(scratch_.begin(), scratch_.end());
  scratch_.erase(std::unique(scratch_.begin(), scratch_.end()), scratch_.end());
  for (int i : scratch_)
    if (aabbs_overlap(boxes_[i].data(), box)) out.push_back(i);
}

}  // namespace stride::sim
