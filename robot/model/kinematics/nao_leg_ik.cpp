#include "robot/model/kinematics/nao_leg_ik.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "robot/nao/nao_dimensions.hpp"

namespace stride::model {
namespace {

constexpr double kL1 = nao::kThighLength;
constexpr double kL2 = nao::kTibiaLength;
constexpr double kCos45 = std::numbers::sqrt2 / 2;

double side_sign(Side side) {
  return side == Side::Left ? 1.0 : -1.0;
}

// Cosine and sine of an angle, carried along so rotations are built without calling trig again.
struct CosSin {
  double c = 1, s = 0;
};

// atan2 through atan of the smaller over the larger coordinate, within an ulp or two of
// std::atan2: glibc's atan takes about 40% of its atan2's time.
double atan2_fast(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  if (!(ax > 0 || ay > 0) || std::isinf(ax) || std::isinf(ay)) return std::atan2(y, x);
  if (ay <= ax) {
    const double a = std::atan(y / x);
    return x > 0 ? a : a + std::copysign(std::numbers::pi, y);
  }
  return std::copysign(std::numbers::pi / 2, y) - std::atan(x / y);
}

// The unit direction of (x, y): cos and sin of atan2(y, x) without evaluating the angle.
CosSin direction(double x, double y) {
  const double r = std::sqrt(x * x + y * y);
  if (!(r > 0)) return {};
  const double inv = 1 / r;
  return {x * inv, y * inv};
}

CosSin sum(CosSin a, CosSin b) {
  return {a.c * b.c - a.s * b.s, a.s * b.c + a.c * b.s};
}

CosSin negated(CosSin a) {
  return {a.c, -a.s};
}

// Elementary rotations applied in place: rows for a rotation on the left, columns on the right.
template <class M>
void rx_times(CosSin a, M& m) {  // m <- Rx(a) m
  for (int j = 0; j < m.cols(); ++j) {
    const double r1 = m(1, j), r2 = m(2, j);
    m(1, j) = a.c * r1 - a.s * r2;
    m(2, j) = a.s * r1 + a.c * r2;
  }
}
template <class M>
void ry_times(CosSin a, M& m) {  // m <- Ry(a) m
  for (int j = 0; j < m.cols(); ++j) {
    const double r0 = m(0, j), r2 = m(2, j);
    m(0, j) = a.c * r0 + a.s * r2;
    m(2, j) = a.c * r2 - a.s * r0;
  }
}
void times_rx(Eigen::Matrix3d& m, CosSin a) {  // m <- m Rx(a)
  for (int i = 0; i < 3; ++i) {
    const double c1 = m(i, 1), c2 = m(i, 2);
    m(i, 1) = a.c * c1 + a.s * c2;
    m(i, 2) = a.c * c2 - a.s * c1;
  }
}
void times_ry(Eigen::Matrix3d& m, CosSin a) {  // m <- m Ry(a)
  for (int i = 0; i < 3; ++i) {
    const double c0 = m(i, 0), c2 = m(i, 2);
    m(i, 0) = a.c * c0 - a.s * c2;
    m(i, 2) = a.s * c0 + a.c * c2;
  }
}

// Rx(s pi/4): the yaw-pitch axis (0, 1, -s)/sqrt(2) is the y axis rolled by -s*45 degrees, so
// the yaw-pitch rotation is Rx(-s pi/4) Ry(q) Rx(s pi/4).
CosSin x45(double s) {
  return {kCos45, s * kCos45};
}

// Yaw-pitch rotation transposed, applied on the left: m <- (Rx(-s pi/4) Ry(q) Rx(s pi/4))^T m.
template <class M>
void hip_yaw_pitch_inverse_times(double s, CosSin q, M& m) {
  rx_times(x45(s), m);
  ry_times(negated(q), m);
  rx_times(x45(-s), m);
}

// Ankle in the hip frame: the sole origin raised by the foot height along the sole's z axis.
Eigen::Vector3d ankle_in_hip(Side side, const Eigen::Isometry3d& sole) {
  const Eigen::Vector3d hip(0, side_sign(side) * nao::kHipOffsetY, -nao::kHipOffsetZ);
  return sole.translation() + nao::kFootHeight * sole.linear().col(2) - hip;
}

// Scales v onto the shell of hip-ankle distances the thigh and tibia can span; flags the result.
void clamp_to_workspace(Eigen::Vector3d& v, LegIkResult& r) {
  constexpr double kMax = kL1 + kL2, kMin = kL1 > kL2 ? kL1 - kL2 : kL2 - kL1;
  const double d = v.norm();
  const double clamped = std::clamp(d, kMin, kMax);
  if (clamped == d) return;
  r.reachable = false;
  r.knee_clamped = d > kMax;
  r.position_error = std::abs(d - clamped);
  v = d > 0 ? Eigen::Vector3d(v * (clamped / d)) : Eigen::Vector3d(0, 0, -clamped);
}

struct Knee {
  double q = 0;
  CosSin cs;
};

// Knee from the hip-ankle distance by the half-angle form, well conditioned near the stretched
// leg; tan(q/2) = sqrt(far/near) gives its cosine and sine without more trig.
Knee knee_from_distance(double d) {
  const double far = std::max(0.0, (kL1 + kL2) * (kL1 + kL2) - d * d);
  const double near = std::max(0.0, d * d - (kL1 - kL2) * (kL1 - kL2));
  const double rf = std::sqrt(far), rn = std::sqrt(near), n = far + near;
  return {2 * atan2_fast(rf, rn), {(near - far) / n, 2 * rf * rn / n}};
}

Knee knee_of(const Eigen::Vector3d& hip_ankle, const LegIkResult& r) {
  return r.knee_clamped ? Knee{} : knee_from_distance(hip_ankle.norm());
}

// Angle of a rotation matrix from its skew part (2 sin) and trace (1 + 2 cos); accurate near 0.
double rotation_angle(const Eigen::Matrix3d& m) {
  const Eigen::Vector3d skew(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
  return atan2_fast(skew.norm(), m.trace() - 1);
}

// Full solution; also hands out cos and sin of HipYawPitch for the other leg.
LegIkResult solve_leg(Side side, const Eigen::Isometry3d& sole_in_torso, CosSin& yaw_pitch) {
  LegIkResult r;
  const Eigen::Matrix3d foot = sole_in_torso.linear();
  // Hip position seen from the ankle: depends only on the knee and the two ankle joints.
  Eigen::Vector3d hip = -(foot.transpose() * ankle_in_hip(side, sole_in_torso));
  clamp_to_workspace(hip, r);
  const Knee knee = knee_of(hip, r);
  // Ankle roll on the branch |roll| <= pi/2 (the joint's range), even when a deeply bent leg puts
  // the hip below the ankle's xy plane.
  const double up = hip.z() >= 0 ? 1.0 : -1.0;
  const double yz = up * std::sqrt(hip.y() * hip.y() + hip.z() * hip.z());
  const CosSin roll = direction(up * hip.z(), up * hip.y());
  // Ankle pitch: angle from the hip direction (hip.x, yz) to the leg's (wx, wz) in one atan2.
  const double wx = -kL1 * knee.cs.s, wz = kL2 + kL1 * knee.cs.c;
  const double pitch_c = wz * yz + wx * hip.x(), pitch_s = wx * yz - wz * hip.x();
  const CosSin pitch = direction(pitch_c, pitch_s);
  // Remaining hip rotation: Rx(s pi/4) R_hip = Ry(yaw-pitch) Rx(s pi/4 + roll) Ry(pitch).
  const double s = side_sign(side);
  Eigen::Matrix3d m = foot;
  times_rx(m, negated(roll));
  times_ry(m, negated(sum(knee.cs, pitch)));
  rx_times(x45(s), m);
  const double b = atan2_fast(s * std::sqrt(m(1, 0) * m(1, 0) + m(1, 2) * m(1, 2)), m(1, 1));
  r.q[0] = atan2_fast(s * m(0, 1), s * m(2, 1));
  yaw_pitch = direction(s * m(2, 1), s * m(0, 1));
  r.q[1] = b - s * std::numbers::pi / 4;  // b in [0, pi] (left) or [-pi, 0]: within (-pi, pi)
  r.q[2] = atan2_fast(s * m(1, 0), -s * m(1, 2));
  r.q[3] = knee.q;
  r.q[4] = atan2_fast(pitch_s, pitch_c);
  r.q[5] = atan2_fast(up * hip.y(), up * hip.z());
  return r;
}

LegIkResult solve_leg_with_hip_yaw_pitch(Side side, const Eigen::Isometry3d& sole_in_torso,
                                         double hip_yaw_pitch, CosSin yaw_pitch) {
  LegIkResult r;
  const double s = side_sign(side);
  Eigen::Vector3d p = ankle_in_hip(side, sole_in_torso);
  hip_yaw_pitch_inverse_times(s, yaw_pitch, p);  // = Rx(roll) * (sagittal leg vector)
  clamp_to_workspace(p, r);
  const Knee knee = knee_of(p, r);
  const double down = p.z() <= 0 ? 1.0 : -1.0;  // hip roll on the branch |roll| <= pi/2
  const CosSin roll = direction(-down * p.z(), down * p.y());
  const double ux = p.x(), uz = -down * std::sqrt(p.y() * p.y() + p.z() * p.z());
  const double wx = -kL2 * knee.cs.s, wz = -(kL1 + kL2 * knee.cs.c);
  // Hip pitch: angle from the leg's (wx, wz) to the ankle direction (ux, uz) in one atan2.
  const double pitch_c = uz * wz + ux * wx, pitch_s = ux * wz - uz * wx;
  const CosSin pitch = direction(pitch_c, pitch_s);
  // Ankle pitch and roll: nearest Ry * Rx factorisation of the remaining rotation.
  Eigen::Matrix3d rest = sole_in_torso.linear();  // (R_yaw-pitch Rx(roll) Ry(pitch + knee))^T R
  hip_yaw_pitch_inverse_times(s, yaw_pitch, rest);
  rx_times(negated(roll), rest);
  ry_times(negated(sum(pitch, knee.cs)), rest);
  const CosSin ankle_pitch = direction(rest(0, 0), -rest(2, 0));
  const CosSin ankle_roll = direction(rest(1, 1), -rest(1, 2));
  r.q = {
      hip_yaw_pitch, atan2_fast(down * p.y(), -down * p.z()), atan2_fast(pitch_s, pitch_c),
      knee.q,        atan2_fast(-rest(2, 0), rest(0, 0)),     atan2_fast(-rest(1, 2), rest(1, 1))};
  Eigen::Matrix3d reached_to_wanted = rest;  // (Ry(ankle pitch) Rx(ankle roll))^T rest
  ry_times(negated(ankle_pitch), reached_to_wanted);
  rx_times(negated(ankle_roll), reached_to_wanted);
  r.orientation_error = rotation_angle(reached_to_wanted);
  return r;
}

}  // namespace

LegIkResult leg_ik(Side side, const Eigen::Isometry3d& sole_in_torso) {
  CosSin yaw_pitch;
  return solve_leg(side, sole_in_torso, yaw_pitch);
}

LegIkResult leg_ik_with_hip_yaw_pitch(Side side, const Eigen::Isometry3d& sole_in_torso,
                                      double hip_yaw_pitch) {
  return solve_leg_with_hip_yaw_pitch(side, sole_in_torso, hip_yaw_pitch,
                                      {std::cos(hip_yaw_pitch), std::sin(hip_yaw_pitch)});
}

LegsIkResult legs_ik(const Eigen::Isometry3d& left_sole, const Eigen::Isometry3d& right_sole) {
  LegsIkResult r;
  CosSin yaw_pitch;
  r.left = solve_leg(Side::Left, left_sole, yaw_pitch);
  r.right = solve_leg_with_hip_yaw_pitch(Side::Right, right_sole, r.left.q[0], yaw_pitch);
  return r;
}

}  // namespace stride::model
