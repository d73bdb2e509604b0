#include "robot/model/kinematics/nao_leg_ik.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "robot/model/kinematics/nao_fk.hpp"
#include "robot/nao/joint_limits.hpp"
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

// atan(t) = t within rounding below this |t| (t^3 / 3 under half an ulp of t).
constexpr double kAtanLinear = 0x1p-27;

double atan_of_ratio(double t) {
  return std::abs(t) < kAtanLinear ? t : std::atan(t);
}

// atan2 through atan of the smaller over the larger coordinate, within an ulp or two of
// std::atan2: glibc's atan takes about 40% of its atan2's time.
double atan2_fast(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  if (!(ax > 0 || ay > 0) || std::isinf(ax) || std::isinf(ay)) return std::atan2(y, x);
  if (ay <= ax) {
    const double a = atan_of_ratio(y / x);
    return x > 0 ? a : a + std::copysign(std::numbers::pi, y);
  }
  return std::copysign(std::numbers::pi / 2, y) - atan_of_ratio(x / y);
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

// Three rows of N scalars (a 3x3 matrix or a column vector), small enough to stay in registers.
template <int N>
struct Rows {
  double a[3][N];
};
using Mat3 = Rows<3>;
using Vec3 = Rows<1>;
Mat3 to_mat3(const Eigen::Matrix3d& m) {
  return {{{m(0, 0), m(0, 1), m(0, 2)}, {m(1, 0), m(1, 1), m(1, 2)}, {m(2, 0), m(2, 1), m(2, 2)}}};
}
Vec3 to_vec3(const Eigen::Vector3d& v) {
  return {{{v.x()}, {v.y()}, {v.z()}}};
}

// Elementary rotations: rows for a rotation on the left, columns on the right.
template <int N>
void rotate_rows(CosSin r, double (&first)[N],
                 double (&second)[N]) {  // (first, second) <- R (first, second)
  for (int j = 0; j < N; ++j) {
    const double u = first[j], v = second[j];
    first[j] = r.c * u - r.s * v;
    second[j] = r.s * u + r.c * v;
  }
}
template <int N>
Rows<N> rx_times(CosSin r, Rows<N> m) {  // Rx(r) m
  rotate_rows(r, m.a[1], m.a[2]);
  return m;
}
template <int N>
Rows<N> ry_times(CosSin r, Rows<N> m) {  // Ry(r) m: z' = c z - s x, x' = c x + s z
  rotate_rows(r, m.a[2], m.a[0]);
  return m;
}
Mat3 times_rx(Mat3 m, CosSin r) {  // m Rx(r)
  for (int i = 0; i < 3; ++i) {
    const double c1 = m.a[i][1], c2 = m.a[i][2];
    m.a[i][1] = r.c * c1 + r.s * c2;
    m.a[i][2] = r.c * c2 - r.s * c1;
  }
  return m;
}
Mat3 times_ry(Mat3 m, CosSin r) {  // m Ry(r)
  for (int i = 0; i < 3; ++i) {
    const double c0 = m.a[i][0], c2 = m.a[i][2];
    m.a[i][0] = r.c * c0 - r.s * c2;
    m.a[i][2] = r.s * c0 + r.c * c2;
  }
  return m;
}

// Rx(s pi/4): the yaw-pitch axis (0, 1, -s)/sqrt(2) is the y axis rolled by -s*45 degrees, so
// the yaw-pitch rotation is Rx(-s pi/4) Ry(q) Rx(s pi/4).
CosSin x45(double s) {
  return {kCos45, s * kCos45};
}

// Yaw-pitch rotation transposed, applied on the left: m <- (Rx(-s pi/4) Ry(q) Rx(s pi/4))^T m.
template <int N>
Rows<N> hip_yaw_pitch_inverse_times(double s, CosSin q, const Rows<N>& m) {
  return rx_times(x45(-s), ry_times(negated(q), rx_times(x45(s), m)));
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
double rotation_angle(const Mat3& m) {
  const double x = m.a[2][1] - m.a[1][2], y = m.a[0][2] - m.a[2][0], z = m.a[1][0] - m.a[0][1];
  return atan2_fast(std::sqrt(x * x + y * y + z * z), m.a[0][0] + m.a[1][1] + m.a[2][2] - 1);
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
  const Mat3 m = rx_times(
      x45(s), times_ry(times_rx(to_mat3(foot), negated(roll)), negated(sum(knee.cs, pitch))));
  const double m10 = m.a[1][0], m12 = m.a[1][2];
  const double b = atan2_fast(s * std::sqrt(m10 * m10 + m12 * m12), m.a[1][1]);
  r.q[0] = atan2_fast(s * m.a[0][1], s * m.a[2][1]);
  yaw_pitch = direction(s * m.a[2][1], s * m.a[0][1]);
  r.q[1] = b - s * std::numbers::pi / 4;  // b in [0, pi] (left) or [-pi, 0]: within (-pi, pi)
  r.q[2] = atan2_fast(s * m10, -s * m12);
  r.q[3] = knee.q;
  r.q[4] = atan2_fast(pitch_s, pitch_c);
  r.q[5] = atan2_fast(up * hip.y(), up * hip.z());
  return r;
}

LegIkResult solve_leg_with_hip_yaw_pitch(Side side, const Eigen::Isometry3d& sole_in_torso,
                                         double hip_yaw_pitch, CosSin yaw_pitch) {
  LegIkResult r;
  const double s = side_sign(side);
  const Vec3 v =
      hip_yaw_pitch_inverse_times(s, yaw_pitch, to_vec3(ankle_in_hip(side, sole_in_torso)));
  Eigen::Vector3d p(v.a[0][0], v.a[1][0], v.a[2][0]);  // = Rx(roll) * (sagittal leg vector)
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
  // (R_yaw-pitch Rx(roll) Ry(pitch + knee))^T R
  const Mat3 rest = ry_times(
      negated(sum(pitch, knee.cs)),
      rx_times(negated(roll),
               hip_yaw_pitch_inverse_times(s, yaw_pitch, to_mat3(sole_in_torso.linear()))));
  const CosSin ankle_pitch = direction(rest.a[0][0], -rest.a[2][0]);
  const CosSin ankle_roll = direction(rest.a[1][1], -rest.a[1][2]);
  r.q = {hip_yaw_pitch,
         atan2_fast(down * p.y(), -down * p.z()),
         atan2_fast(pitch_s, pitch_c),
         knee.q,
         atan2_fast(-rest.a[2][0], rest.a[0][0]),
         atan2_fast(-rest.a[1][2], rest.a[1][1])};
  // (Ry(ankle pitch) Rx(ankle roll))^T rest: the rotation the ankle cannot reach.
  r.orientation_error =
      rotation_angle(rx_times(negated(ankle_roll), ry_times(negated(ankle_pitch), rest)));
  return r;
}

LegIkResult with_limits(Side side, LegIkResult r) {
  r.beyond_limits = leg_limit_violations(side, r.q);
  return r;
}

}  // namespace

std::uint8_t leg_limit_violations(Side side, const LegAngles& q) {
  const auto joints = chain_joints(leg_chain(side));
  std::uint8_t bits = 0;
  for (int i = 0; i < kLegJoints; ++i) {
    const auto& lim = nao::kJointLimits[hal::index(joints[i])];
    if (!(q[i] >= lim.lower && q[i] <= lim.upper)) bits |= static_cast<std::uint8_t>(1u << i);
  }
  return bits;
}

LegIkResult leg_ik(Side side, const Eigen::Isometry3d& sole_in_torso) {
  CosSin yaw_pitch;
  return with_limits(side, solve_leg(side, sole_in_torso, yaw_pitch));
}

LegIkResult leg_ik_with_hip_yaw_pitch(Side side, const Eigen::Isometry3d& sole_in_torso,
                                      double hip_yaw_pitch) {
  return with_limits(
      side, solve_leg_with_hip_yaw_pitch(side, sole_in_torso, hip_yaw_pitch,
                                         {std::cos(hip_yaw_pitch), std::sin(hip_yaw_pitch)}));
}

LegsIkResult legs_ik(const Eigen::Isometry3d& left_sole, const Eigen::Isometry3d& right_sole) {
  LegsIkResult r;
  CosSin yaw_pitch;
  r.left = with_limits(Side::Left, solve_leg(Side::Left, left_sole, yaw_pitch));
  r.right = with_limits(
      Side::Right, solve_leg_with_hip_yaw_pitch(Side::Right, right_sole, r.left.q[0], yaw_pitch));
  return r;
}

namespace {
Eigen::Isometry3d flat_sole(const Eigen::Vector3d& at, double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  t.translation() = at;
  return t;
}
}  // namespace

LegsIkResult legs_ik_upright(const Eigen::Vector3d& left_sole, double left_yaw,
                             const Eigen::Vector3d& right_sole, double right_yaw) {
  return legs_ik(flat_sole(left_sole, left_yaw), flat_sole(right_sole, right_yaw));
}

double torso_yaw_between(double left_yaw, double right_yaw) {
  const double d = std::remainder(right_yaw - left_yaw, 2 * std::numbers::pi);
  return std::remainder(left_yaw + 0.5 * d, 2 * std::numbers::pi);
}

namespace {

struct TurnedTry {
  LegsIkResult legs;
  double yaw_error = 0.0;  // signed: the right foot's reached yaw minus its wanted one
};

TurnedTry turned_at(double torso_yaw, const Eigen::Vector3d& left, double left_yaw,
                    const Eigen::Vector3d& right, double right_yaw) {
  const Eigen::Matrix3d to_torso =
      Eigen::AngleAxisd(-torso_yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const double wanted = std::remainder(right_yaw - torso_yaw, 2 * std::numbers::pi);
  TurnedTry t;
  t.legs =
      legs_ik_upright(to_torso * left, std::remainder(left_yaw - torso_yaw, 2 * std::numbers::pi),
                      to_torso * right, wanted);
  const Eigen::Matrix3d r = leg_fk(Side::Right, t.legs.right.q).linear();
  t.yaw_error = std::remainder(std::atan2(r(1, 0), r(0, 0)) - wanted, 2 * std::numbers::pi);
  return t;
}

}  // namespace

TurnedLegsIkResult legs_ik_turned(const Eigen::Vector3d& left, double left_yaw,
                                  const Eigen::Vector3d& right, double right_yaw) {
  constexpr int kIterations = 12;
  constexpr double kTolerance = 1e-12;  // rad
  double y0 = torso_yaw_between(left_yaw, right_yaw), y1 = y0 + 1e-3;
  TurnedTry t0 = turned_at(y0, left, left_yaw, right, right_yaw);
  TurnedLegsIkResult best{t0.legs, y0, t0.yaw_error};
  for (int i = 0; i < kIterations && std::abs(best.yaw_error) > kTolerance; ++i) {
    const TurnedTry t1 = turned_at(y1, left, left_yaw, right, right_yaw);
    if (std::abs(t1.yaw_error) < std::abs(best.yaw_error)) best = {t1.legs, y1, t1.yaw_error};
    const double slope = (t1.yaw_error - t0.yaw_error) / (y1 - y0);
    if (!(std::abs(slope) > 1e-9)) break;  // the yaw no longer moves the foot (out of reach)
    y0 = y1;
    t0 = t1;
    y1 -= t1.yaw_error / slope;
  }
  best.torso_yaw = std::remainder(best.torso_yaw, 2 * std::numbers::pi);
  best.yaw_error = std::abs(best.yaw_error);
  return best;
}

}  // namespace stride::model
