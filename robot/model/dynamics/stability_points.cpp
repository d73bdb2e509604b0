#include "robot/model/dynamics/stability_points.hpp"

#include "robot/nao/nao_dimensions.hpp"

namespace stride::model {
namespace {

// Moment balance about a ground point for "forces" f_i at p_i and extra moments: the point where
// the tangential moment vanishes (shared by the ZMP of Eq. 2.3 and the FRI).
struct MomentSums {
  double fz = 0, x_fz = 0, y_fz = 0, h_fx = 0, h_fy = 0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  void add(const Eigen::Vector3d& p, const Eigen::Vector3d& f, double ground_z) {
    const double h = p.z() - ground_z;
    fz += f.z();
    x_fz += p.x() * f.z();
    y_fz += p.y() * f.z();
    h_fx += h * f.x();
    h_fy += h * f.y();
  }
  // Solves (sum (p_i - F) x f_i)_xy = moment_xy for F on the ground.
  Eigen::Vector2d point() const {
    return {(x_fz - h_fx + moment.y()) / fz, (y_fz - h_fy - moment.x()) / fz};
  }
};

// Inertial-plus-gravity force of a segment: m (a - g) with g = (0, 0, -gravity), sign flipped so
// that its z is the positive supported weight.
Eigen::Vector3d supported_force(const SegmentMotion& s, double gravity) {
  return s.mass * Eigen::Vector3d(s.com_acceleration.x(), s.com_acceleration.y(),
                                  s.com_acceleration.z() + gravity);
}

}  // namespace

Eigen::Vector2d zmp_multibody(std::span<const SegmentMotion> segments, double ground_z,
                              double gravity) {
  MomentSums sums;
  for (const SegmentMotion& s : segments) {
    sums.add(s.com, supported_force(s, gravity), ground_z);
    sums.moment -= s.angular_momentum_rate;  // Eq. 2.2: inertial moments balance gravity
  }
  return sums.point();  // Eq. 2.3
}

Eigen::Vector2d zmp_point_mass(const Eigen::Vector3d& com, const Eigen::Vector3d& com_acceleration,
                               double mass, const Eigen::Vector3d& angular_momentum_rate,
                               double ground_z, double gravity) {
  const double fz = mass * (com_acceleration.z() + gravity);
  const double h = com.z() - ground_z;
  // Eq. 2.5
  return {(mass * (com.x() * (com_acceleration.z() + gravity) - h * com_acceleration.x()) -
           angular_momentum_rate.y()) /
              fz,
          (mass * (com.y() * (com_acceleration.z() + gravity) - h * com_acceleration.y()) +
           angular_momentum_rate.x()) /
              fz};
}

std::optional<Eigen::Vector3d> centre_of_pressure(std::span<const double> forces,
                                                  std::span<const Eigen::Vector3d> positions,
                                                  double min_total_force) {
  double total = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const size_t n = std::min(forces.size(), positions.size());
  for (size_t i = 0; i < n; ++i) {
    total += forces[i];
    sum += forces[i] * positions[i];
  }
  if (!(total > min_total_force)) return std::nullopt;
  return Eigen::Vector3d(sum / total);
}

std::optional<Eigen::Vector3d> nao_fsr_centre_of_pressure(std::span<const double, 8> forces,
                                                          const Eigen::Isometry3d& left_sole,
                                                          const Eigen::Isometry3d& right_sole,
                                                          double min_total_force) {
  std::array<Eigen::Vector3d, 8> p;
  for (int i = 0; i < 8; ++i) {  // FSRs lie in the sole plane (z = -FootHeight below the ankle)
    const Eigen::Vector2d& xy = nao::kFsrPositions[i];
    p[i] = (i < 4 ? left_sole : right_sole) * Eigen::Vector3d(xy.x(), xy.y(), 0);
  }
  return centre_of_pressure(forces, p, min_total_force);
}

Eigen::Vector2d foot_rotation_indicator(const SegmentMotion& stance_foot,
                                        std::span<const SegmentMotion> rest_of_body,
                                        double ground_z, double gravity) {
  MomentSums sums;  // Sec. 2.1.2: foot static, the others with their inertial forces
  sums.add(stance_foot.com, Eigen::Vector3d(0, 0, stance_foot.mass * gravity), ground_z);
  for (const SegmentMotion& s : rest_of_body) {
    sums.add(s.com, supported_force(s, gravity), ground_z);
    sums.moment -= s.angular_momentum_rate;  // inertial moments balance gravity, as in Eq. 2.2
  }
  return sums.point();
}

Eigen::Vector2d cmp_from_ground_reaction(const Eigen::Vector3d& com,
                                         const Eigen::Vector3d& ground_reaction_force,
                                         double ground_z) {
  const double t = (com.z() - ground_z) / ground_reaction_force.z();
  return {com.x() - t * ground_reaction_force.x(), com.y() - t * ground_reaction_force.y()};
}

Eigen::Vector2d cmp_from_com_motion(const Eigen::Vector3d& com,
                                    const Eigen::Vector3d& com_acceleration, double ground_z,
                                    double gravity) {
  return cmp_from_ground_reaction(
      com,
      Eigen::Vector3d(com_acceleration.x(), com_acceleration.y(), com_acceleration.z() + gravity),
      ground_z);
}

}  // namespace stride::model
