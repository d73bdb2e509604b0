#include "simulator/devices/fsr_device.hpp"

#include <algorithm>
#include <limits>

#include "robot/core/error.hpp"

namespace stride::sim {

LoadSplitter::LoadSplitter(const std::array<Eigen::Vector2d, 4>& points) {
  for (int mask = 1; mask < 16; ++mask) {
    Subset a(3, __builtin_popcount(mask));
    int col = 0;
    for (int i = 0; i < 4; ++i)
      if (mask & (1 << i)) a.col(col++) = Eigen::Vector3d(1.0, points[i].x(), points[i].y());
    supports_.push_back({mask, a, a.completeOrthogonalDecomposition()});
  }
}

std::array<double, 4> LoadSplitter::split(double load, const Eigen::Vector2d& cop) const {
  std::array<double, 4> best{};
  if (load <= 0) return best;
  const Eigen::Vector3d b(1.0, cop.x(), cop.y());  // per unit load: sum f = 1, sum f p = cop
  double best_residual = std::numeric_limits<double>::infinity();
  double best_norm = std::numeric_limits<double>::infinity();
  // Four unknowns: try every support subset, keep the feasible one that best meets the moments.
  for (const Support& s : supports_) {
    // Least-norm least-squares solution on this subset.
    const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1> f = s.cod.solve(b);
    if ((f.array() < -1e-12).any()) continue;
    const double residual = (s.a * f - b).norm();
    const double norm = f.squaredNorm();
    if (residual < best_residual - 1e-12 ||
        (std::abs(residual - best_residual) <= 1e-12 && norm < best_norm)) {
      best_residual = residual;
      best_norm = norm;
      int col = 0;
      for (int i = 0; i < 4; ++i) best[i] = (s.mask & (1 << i)) ? f[col++] * load : 0.0;
    }
  }
  return best;
}

FsrDevice::FsrDevice(const RobotBody& body, int robot_index, const FsrSpec& spec, NoiseSource noise)
    : spec_(spec),
      splitter_(spec.positions),
      link_(body.model().link_index(spec.link)),
      robot_(robot_index),
      noise_(noise) {
  if (link_ < 0)
    throw Error("FSR link '" + spec.link + "' is not a link of " + body.model().source);
}

void FsrDevice::accumulate(const RobotBody& body, const PhysicsWorld& world) {
  const Eigen::Isometry3d foot = body.link_pose(link_);
  const Eigen::Isometry3d inv = foot.inverse();
  const Eigen::Vector3d normal = foot.linear().col(2);  // sole normal in the world
  double step_load = 0;
  for (const ContactRecord& c : world.contacts()) {
    const bool is_a = c.a->robot == robot_ && c.a->link == link_;
    const bool is_b = c.b->robot == robot_ && c.b->link == link_;
    if (is_a == is_b) continue;  // not this foot, or the foot against itself
    const double fn = (is_a ? c.force_on_a : c.force_on_b).dot(normal);
    if (fn <= 0) continue;  // a sensor only measures pressing
    const Eigen::Vector3d p = inv * c.position;
    load_sum_ += fn;  // per contact, as before: the frame mean keeps its bits
    step_load += fn;
    moment_sum_ += fn * p.head<2>();
  }
  step_loads_.push_back(step_load);
  ++steps_;
}

std::array<double, 4> FsrDevice::sample(bool noise_on) {
  std::array<double, 4> out{};
  if (steps_ > 0 && load_sum_ > 0) {
    const double load = load_sum_ / steps_;
    out = splitter_.split(load, moment_sum_ / load_sum_);
  }
  for (double& f : out)
    f = std::clamp(f + (noise_on ? noise_.gaussian(spec_.noise) : 0.0), 0.0, spec_.max_force);
  load_sum_ = 0;
  moment_sum_.setZero();
  steps_ = 0;
  std::swap(step_loads_, closed_loads_);
  step_loads_.clear();
  return out;
}

}  // namespace stride::sim
