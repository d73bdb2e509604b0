#include "robot/model/kinematics/nao_leg_ik.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "robot/nao/nao_dimensions.hpp"

namespace stride::model {
namespace {

using std::numbers::pi;
constexpr double kL1 = nao::kThighLength;
constexpr double kL2 = nao::kTibiaLength;

double side_sign(Side side) {
  return side == Side::Left ? 1.0 : -1.0;
}

Eigen::Matrix3d rx(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
Eigen::Matrix3d ry(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix();
}

// The yaw-pitch axis (0, 1, -s)/sqrt(2) is the y axis rolled by -s*45 degrees.
Eigen::Matrix3d hip_yaw_pitch_rotation(Side side, double q) {
  const double s = side_sign(side);
  return rx(-s * pi / 4) * ry(q) * rx(s * pi / 4);
}

double wrap(double a) {
  return std::remainder(a, 2 * pi);
}

struct AnkleTarget {
  Eigen::Vector3d position;  // ankle in the hip frame
  Eigen::Matrix3d rotation;  // foot orientation
};

AnkleTarget ankle_target(Side side, const Eigen::Isometry3d& sole) {
  const Eigen::Vector3d hip(0, side_sign(side) * nao::kHipOffsetY, -nao::kHipOffsetZ);
  return {sole * Eigen::Vector3d(0, 0, nao::kFootHeight) - hip, sole.linear()};
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

// Knee from the hip-ankle distance by the half-angle form, well conditioned near the stretched leg.
double knee_angle(double d) {
  const double far = (kL1 + kL2) * (kL1 + kL2) - d * d;
  const double near = d * d - (kL1 - kL2) * (kL1 - kL2);
  return 2 * std::atan2(std::sqrt(std::max(0.0, far)), std::sqrt(std::max(0.0, near)));
}

}  // namespace

LegIkResult leg_ik(Side side, const Eigen::Isometry3d& sole_in_torso) {
  LegIkResult r;
  const AnkleTarget t = ankle_target(side, sole_in_torso);
  // Hip position seen from the ankle: depends only on the knee and the two ankle joints.
  Eigen::Vector3d hip = -(t.rotation.transpose() * t.position);
  clamp_to_workspace(hip, r);
  const double knee = r.knee_clamped ? 0.0 : knee_angle(hip.norm());
  // Ankle roll on the branch |roll| <= pi/2 (the joint's range), even when a deeply bent leg puts
  // the hip below the ankle's xy plane.
  const double up = hip.z() >= 0 ? 1.0 : -1.0;
  const double ankle_roll = std::atan2(up * hip.y(), up * hip.z());
  const double wx = -kL1 * std::sin(knee), wz = kL2 + kL1 * std::cos(knee);
  const double ankle_pitch =
      wrap(std::atan2(wx, wz) - std::atan2(hip.x(), up * std::hypot(hip.y(), hip.z())));
  // Remaining hip rotation: Rx(s pi/4) R_hip = Ry(yaw-pitch) Rx(s pi/4 + roll) Ry(pitch).
  const double s = side_sign(side);
  const Eigen::Matrix3d m =
      rx(s * pi / 4) * t.rotation * rx(-ankle_roll) * ry(-(knee + ankle_pitch));
  const double b = std::atan2(s * std::hypot(m(1, 0), m(1, 2)), m(1, 1));
  r.q[0] = std::atan2(s * m(0, 1), s * m(2, 1));
  r.q[1] = wrap(b - s * pi / 4);
  r.q[2] = std::atan2(s * m(1, 0), -s * m(1, 2));
  r.q[3] = knee;
  r.q[4] = ankle_pitch;
  r.q[5] = ankle_roll;
  return r;
}

LegIkResult leg_ik_with_hip_yaw_pitch(Side side, const Eigen::Isometry3d& sole_in_torso,
                                      double hip_yaw_pitch) {
  LegIkResult r;
  const AnkleTarget t = ankle_target(side, sole_in_torso);
  const Eigen::Matrix3d yaw_pitch = hip_yaw_pitch_rotation(side, hip_yaw_pitch);
  Eigen::Vector3d p = yaw_pitch.transpose() * t.position;  // = Rx(roll) * (sagittal leg vector)
  clamp_to_workspace(p, r);
  const double knee = r.knee_clamped ? 0.0 : knee_angle(p.norm());
  const double down = p.z() <= 0 ? 1.0 : -1.0;  // hip roll on the branch |roll| <= pi/2
  const double roll = std::atan2(down * p.y(), -down * p.z());
  const double ux = p.x(), uz = -down * std::hypot(p.y(), p.z());
  const double wx = -kL2 * std::sin(knee), wz = -(kL1 + kL2 * std::cos(knee));
  const double pitch = wrap(std::atan2(ux, uz) - std::atan2(wx, wz));
  // Ankle pitch and roll: nearest Ry * Rx factorisation of the remaining rotation.
  const Eigen::Matrix3d rest = (yaw_pitch * rx(roll) * ry(pitch + knee)).transpose() * t.rotation;
  const double ankle_pitch = std::atan2(-rest(2, 0), rest(0, 0));
  const double ankle_roll = std::atan2(-rest(1, 2), rest(1, 1));
  r.q = {hip_yaw_pitch, roll, pitch, knee, ankle_pitch, ankle_roll};
  const Eigen::Matrix3d reached = ry(ankle_pitch) * rx(ankle_roll);
  r.orientation_error = Eigen::AngleAxisd(reached.transpose() * rest).angle();
  return r;
}

LegsIkResult legs_ik(const Eigen::Isometry3d& left_sole, const Eigen::Isometry3d& right_sole) {
  LegsIkResult r;
  r.left = leg_ik(Side::Left, left_sole);
  r.right = leg_ik_with_hip_yaw_pitch(Side::Right, right_sole, r.left.q[0]);
  return r;
}

}  // namespace stride::model
