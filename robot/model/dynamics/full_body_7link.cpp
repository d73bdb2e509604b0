#include "robot/model/dynamics/full_body_7link.hpp"

#include <array>

#include "robot/model/dynamics/dual.hpp"
#include "robot/model/dynamics/swing_leg_3d.hpp"

namespace stride::model {
namespace {

enum Q { kAr1, kAp1, kK1, kHp1, kHr1, kHr2, kHp2, kK2, kAp2, kAr2, kTp, kTr };
constexpr int kLinks = 7;  // foot1, tibia1, thigh1, torso, thigh2, tibia2, foot2

template <typename T>
using Vec3 = std::array<T, 3>;

template <typename T>
Vec3<T> axpy(const Vec3<T>& base, double length, const Vec3<T>& dir) {
  return {base[0] + length * dir[0], base[1] + length * dir[1], base[2] + length * dir[2]};
}

// Link directions of the script: pitch P from the vertical, roll R; stance links point up,
// swing links down.
template <typename T>
Vec3<T> up(const T& p, const T& r) {
  using std::cos, std::sin;
  return {sin(p) * cos(r), -sin(r), cos(p) * cos(r)};
}
template <typename T>
Vec3<T> down(const T& p, const T& r) {
  using std::cos, std::sin;
  return {sin(p) * cos(r), -sin(r), -cos(p) * cos(r)};
}

// CoM of every link (in link order) and the swing sole point, from the stance sole.
template <typename T>
void positions(const FullBodyParams& p, const std::array<T, kFullBodyDof>& q,
               std::array<Vec3<T>, kLinks>& com, Vec3<T>& swing_sole) {
  using std::cos, std::sin;
  const Vec3<T> zero{T(0.0), T(0.0), T(0.0)};
  const Vec3<T> d_foot1 = up(q[kAp1] + q[kK1] + q[kHp1], q[kAr1] + q[kHr1]);
  const Vec3<T> d_tibia1 = up(q[kK1] + q[kHp1], q[kHr1]);
  const Vec3<T> d_thigh1 = up(q[kHp1], q[kHr1]);
  const Vec3<T> d_torso = {sin(q[kTp]) * cos(q[kTr]), sin(q[kTr]), cos(q[kTp]) * cos(q[kTr])};
  const Vec3<T> d_thigh2 = down(q[kHp2], q[kHr2]);
  const Vec3<T> d_tibia2 = down(q[kHp2] + q[kK2], q[kHr2]);
  const Vec3<T> d_foot2 = down(q[kHp2] + q[kK2] + q[kAp2], q[kHr2] + q[kAr2]);
  const Vec3<T> ankle1 = axpy(zero, p.l_foot, d_foot1);
  const Vec3<T> knee1 = axpy(ankle1, p.l_tibia, d_tibia1);
  const Vec3<T> hip = axpy(knee1, p.l_thigh, d_thigh1);
  const Vec3<T> knee2 = axpy(hip, p.l_thigh, d_thigh2);
  const Vec3<T> ankle2 = axpy(knee2, p.l_tibia, d_tibia2);
  com = {axpy(zero, p.foot1.com_offset, d_foot1),    axpy(ankle1, p.tibia1.com_offset, d_tibia1),
         axpy(knee1, p.thigh1.com_offset, d_thigh1), axpy(hip, p.torso.com_offset, d_torso),
         axpy(hip, p.thigh2.com_offset, d_thigh2),   axpy(knee2, p.tibia2.com_offset, d_tibia2),
         axpy(ankle2, p.foot2.com_offset, d_foot2)};
  swing_sole = axpy(ankle2, p.l_foot, d_foot2);
}

std::array<const FullBodyLink*, kLinks> links(const FullBodyParams& p) {
  return {&p.foot1, &p.tibia1, &p.thigh1, &p.torso, &p.thigh2, &p.tibia2, &p.foot2};
}

// Pitch and roll rates of every link as sums of coordinate rates (the script's rotational KE),
// as bit masks over the coordinates.
constexpr int bits(std::initializer_list<int> coordinates) {
  int m = 0;
  for (int c : coordinates) m |= 1 << c;
  return m;
}
constexpr std::array<int, kLinks> kPitchRates = {
    bits({kAp1, kK1, kHp1}), bits({kK1, kHp1}),      bits({kHp1}), bits({kTp}), bits({kHp2}),
    bits({kHp2, kK2}),       bits({kHp2, kK2, kAp2})};
constexpr std::array<int, kLinks> kRollRates = {bits({kAr1, kHr1}), bits({kHr1}), bits({kHr1}),
                                                bits({kTr}),        bits({kHr2}), bits({kHr2}),
                                                bits({kHr2, kAr2})};

// H(q) for scalar T: sum_i m_i Jv_i^T Jv_i + rotational terms; Jv by one dual pass per column.
template <typename T>
void inertia(const FullBodyParams& p, const std::array<T, kFullBodyDof>& q,
             std::array<std::array<T, kFullBodyDof>, kFullBodyDof>& h) {
  using D = DualOf<T>;
  std::array<std::array<Vec3<T>, kFullBodyDof>, kLinks> jv;  // jv[link][column]
  for (int c = 0; c < kFullBodyDof; ++c) {
    std::array<D, kFullBodyDof> qd;
    for (int j = 0; j < kFullBodyDof; ++j) qd[j] = D(q[j], T(j == c ? 1.0 : 0.0));
    std::array<Vec3<D>, kLinks> com;
    Vec3<D> sole;
    positions(p, qd, com, sole);
    for (int l = 0; l < kLinks; ++l)
      for (int k = 0; k < 3; ++k) jv[l][c][k] = com[l][k].d;
  }
  const auto link = links(p);
  for (int r = 0; r < kFullBodyDof; ++r)
    for (int c = 0; c < kFullBodyDof; ++c) {
      T s(0.0);
      for (int l = 0; l < kLinks; ++l)
        s += link[l]->mass *
             (jv[l][r][0] * jv[l][c][0] + jv[l][r][1] * jv[l][c][1] + jv[l][r][2] * jv[l][c][2]);
      h[r][c] = s;
    }
  for (int l = 0; l < kLinks; ++l)
    for (int r = 0; r < kFullBodyDof; ++r)
      for (int c = 0; c < kFullBodyDof; ++c) {
        if ((kPitchRates[l] >> r & 1) && (kPitchRates[l] >> c & 1)) h[r][c] += T(link[l]->iyy);
        if ((kRollRates[l] >> r & 1) && (kRollRates[l] >> c & 1)) h[r][c] += T(link[l]->ixx);
      }
}

double potential(const FullBodyParams& p, const std::array<double, kFullBodyDof>& q) {
  std::array<Vec3<double>, kLinks> com;
  Vec3<double> sole;
  positions(p, q, com, sole);
  double e = 0;
  const auto link = links(p);
  for (int l = 0; l < kLinks; ++l) e += link[l]->mass * p.gravity * com[l][2];
  return e;
}

std::array<double, kFullBodyDof> to_array(const FullBodyVector& q) {
  std::array<double, kFullBodyDof> a;
  for (int i = 0; i < kFullBodyDof; ++i) a[i] = q[i];
  return a;
}

}  // namespace

FullBodyParams nao_full_body_params() {
  const Leg3dData leg = thesis_3d_leg();
  FullBodyParams p;
  p.l_thigh = leg.l1;
  p.l_tibia = leg.l2;
  p.l_foot = leg.l3;
  // Stance links are measured from the sole upwards, swing links from the hip downwards.
  p.thigh2 = {leg.m1, leg.b1, leg.ixx1, leg.iyy1};
  p.tibia2 = {leg.m2, leg.b2, leg.ixx2, leg.iyy2};
  p.foot2 = {leg.m3, leg.b3, leg.ixx3, leg.iyy3};
  p.foot1 = {leg.m3, leg.l3 - leg.b3, leg.ixx3, leg.iyy3};
  p.tibia1 = {leg.m2, leg.l2 - leg.b2, leg.ixx2, leg.iyy2};
  p.thigh1 = {leg.m1, leg.l1 - leg.b1, leg.ixx1, leg.iyy1};
  const double legs = 2 * (leg.m1 + leg.m2 + leg.m3);
  p.torso = {5.183 - legs, 0.1, 0.03, 0.03};
  return p;
}

FullBodyTerms full_body_terms(const FullBodyParams& p, const FullBodyVector& q,
                              const FullBodyVector& qd) {
  FullBodyTerms t;
  const auto qa = to_array(q);
  // H and dH/dq_k from nested duals: one pass per k.
  std::array<std::array<std::array<double, kFullBodyDof>, kFullBodyDof>, kFullBodyDof> dh;
  for (int k = 0; k < kFullBodyDof; ++k) {
    std::array<Dual, kFullBodyDof> qk;
    for (int j = 0; j < kFullBodyDof; ++j) qk[j] = Dual(qa[j], j == k ? 1.0 : 0.0);
    std::array<std::array<Dual, kFullBodyDof>, kFullBodyDof> h;
    inertia(p, qk, h);
    for (int r = 0; r < kFullBodyDof; ++r)
      for (int c = 0; c < kFullBodyDof; ++c) {
        dh[k][r][c] = h[r][c].d;
        if (k == 0) t.inertia(r, c) = h[r][c].v;
      }
  }
  // The script's loop: C_kj = sum_i 1/2 (dH_kj/dq_i + dH_ki/dq_j - dH_ij/dq_k) q'_i.
  t.coriolis.setZero();
  for (int k = 0; k < kFullBodyDof; ++k)
    for (int j = 0; j < kFullBodyDof; ++j)
      for (int i = 0; i < kFullBodyDof; ++i)
        t.coriolis(k, j) += 0.5 * (dh[i][k][j] + dh[j][k][i] - dh[k][i][j]) * qd[i];  // Eq. C.14
  // G = dP/dq and J = d(swing sole)/dq, one dual pass per coordinate.
  const auto link = links(p);
  for (int c = 0; c < kFullBodyDof; ++c) {
    std::array<Dual, kFullBodyDof> qc;
    for (int j = 0; j < kFullBodyDof; ++j) qc[j] = Dual(qa[j], j == c ? 1.0 : 0.0);
    std::array<Vec3<Dual>, kLinks> com;
    Vec3<Dual> sole;
    positions(p, qc, com, sole);
    double g = 0;
    for (int l = 0; l < kLinks; ++l) g += link[l]->mass * p.gravity * com[l][2].d;
    t.gravity[c] = g;
    for (int r = 0; r < 3; ++r) t.swing_jacobian(r, c) = sole[r].d;
  }
  // B = (dPhi_0/dq)^T [I10; 0]: Phi_0 maps the coordinates to the robot's joint angles, the
  // hips measured against the torso (the script's Phi_0, signs as it has them).
  Eigen::Matrix<double, kFullBodyDof, kFullBodyDof> dphi = FullBodyMatrix::Identity();
  dphi(kHp1, kTp) = 1;
  dphi(kHr1, kTr) = -1;
  dphi(kHr2, kTr) = 1;
  dphi(kHp2, kTp) = 1;
  t.input = dphi.transpose().leftCols<10>();
  return t;
}

Eigen::Vector3d full_body_swing_foot(const FullBodyParams& p, const FullBodyVector& q) {
  std::array<Vec3<double>, kLinks> com;
  Vec3<double> sole;
  positions(p, to_array(q), com, sole);
  return {sole[0], sole[1], sole[2]};
}

double full_body_energy(const FullBodyParams& p, const FullBodyVector& q,
                        const FullBodyVector& qd) {
  std::array<std::array<double, kFullBodyDof>, kFullBodyDof> h;
  inertia(p, to_array(q), h);
  double k = 0;
  for (int r = 0; r < kFullBodyDof; ++r)
    for (int c = 0; c < kFullBodyDof; ++c) k += 0.5 * qd[r] * h[r][c] * qd[c];
  return k + potential(p, to_array(q));
}

}  // namespace stride::model
