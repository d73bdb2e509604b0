#include "robot/model/dynamics/swing_leg_3d.hpp"

#include <array>

#include <Eigen/Cholesky>

#include <Eigen/Cholesky>

#include "robot/model/dynamics/dual.hpp"

namespace stride::model {
namespace {

// The three CoM positions (Eq. C.16, Eq. C.18, Eq. C.20) are sums of lengths times unit directions
// u1 (thigh), u2 (tibia), u3 (foot); U[k] = du_k/dq (3 x 5). With them the kinetic energy is
//   K = 1/2 q'^T [ (J1+J3+J5) U1'U1 + (J2+J6) U2'U2 + J4 U3'U3 + J9 (U1'U2 + U2'U1)
//                + J7 (U1'U3 + U3'U1) + J8 (U2'U3 + U3'U2) + rotational terms ] q'
// and P = J15 u1z + J16 u2z + J17 u3z: every term is one parameter times a matrix of q.
template <typename T>
using Dir = std::array<std::array<T, 5>, 3>;  // 3 x 5 direction Jacobian

template <typename T>
using Basis = std::array<std::array<std::array<T, 5>, 5>, 17>;  // H = sum_k a_k Basis[k]

template <typename T>
void directions(const std::array<T, 5>& q, Dir<T>& u1, Dir<T>& u2, Dir<T>& u3,
                std::array<T, 3>& uz) {
  using std::cos, std::sin;
  const T a1 = q[0], t1 = q[1], t12 = q[1] + q[2], t123 = q[1] + q[2] + q[3], a12 = q[0] + q[4];
  const T ca1 = cos(a1), sa1 = sin(a1), ca12 = cos(a12), sa12 = sin(a12);
  for (auto* u : {&u1, &u2, &u3})
    for (auto& row : *u) row.fill(T(0));
  // u = (ca st, sa, -ca ct): du/d(roll) and du/d(pitch) for the joints the link hangs on.
  const auto roll = [](Dir<T>& u, int col, const T& ca, const T& sa, const T& t) {
    u[0][col] = -sa * sin(t);
    u[1][col] = ca;
    u[2][col] = sa * cos(t);
  };
  const auto pitch = [](Dir<T>& u, int col, const T& ca, const T& t) {
    u[0][col] = ca * cos(t);
    u[2][col] = ca * sin(t);
  };
  roll(u1, 0, ca1, sa1, t1);
  pitch(u1, 1, ca1, t1);
  roll(u2, 0, ca1, sa1, t12);
  for (int c : {1, 2}) pitch(u2, c, ca1, t12);
  for (int c : {0, 4}) roll(u3, c, ca12, sa12, t123);
  for (int c : {1, 2, 3}) pitch(u3, c, ca12, t123);
  uz = {-ca1 * cos(t1), -ca1 * cos(t12), -ca12 * cos(t123)};
}

template <typename T>
void basis(const std::array<T, 5>& q, Basis<T>& b) {
  Dir<T> u1, u2, u3;
  std::array<T, 3> uz;
  directions(q, u1, u2, u3, uz);
  for (auto& m : b)
    for (auto& row : m) row.fill(T(0));
  const auto add_product = [&](int k, const Dir<T>& x, const Dir<T>& y, bool symmetrise) {
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        T s = x[0][i] * y[0][j] + x[1][i] * y[1][j] + x[2][i] * y[2][j];
        if (symmetrise) s += y[0][i] * x[0][j] + y[1][i] * x[1][j] + y[2][i] * x[2][j];
        b[k][i][j] += s;
      }
  };
  for (int k : {0, 2, 4}) add_product(k, u1, u1, false);  // J1, J3, J5
  for (int k : {1, 5}) add_product(k, u2, u2, false);     // J2, J6
  add_product(3, u3, u3, false);                          // J4
  add_product(6, u1, u3, true);                           // J7
  add_product(7, u2, u3, true);                           // J8
  add_product(8, u1, u2, true);                           // J9
  // Eq. C.22, rotational terms: angular rates are sums of joint rates.
  const auto add_rate = [&](int k, std::initializer_list<int> joints) {
    for (int i : joints)
      for (int j : joints) b[k][i][j] += T(1);
  };
  add_rate(9, {0});         // J10 = Ixx1 + Ixx2: a1'
  add_rate(10, {0, 4});     // J11 = Ixx3: a1' + a2'
  add_rate(11, {1});        // J12 = Iyy1: t1'
  add_rate(12, {1, 2});     // J13 = Iyy2: t1' + t2'
  add_rate(13, {1, 2, 3});  // J14 = Iyy3: t1' + t2' + t3'
}

// Gravity basis: d(u_kz)/dq for J15..J17.
void gravity_basis(const Vector5d& q, std::array<Vector5d, 3>& g) {
  std::array<double, 5> qa;
  for (int i = 0; i < 5; ++i) qa[i] = q[i];
  Dir<double> u1, u2, u3;
  std::array<double, 3> uz;
  directions(qa, u1, u2, u3, uz);
  const Dir<double>* u[3] = {&u1, &u2, &u3};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 5; ++i) g[k][i] = (*u[k])[2][i];
}

struct BasisWithDerivatives {
  Basis<double> h;
  std::array<Basis<double>, 5> dh;  // dh[i] = d(basis)/dq_i
};

void basis_with_derivatives(const Vector5d& q, BasisWithDerivatives& out) {
  Basis<Dual> b;
  for (int i = 0; i < 5; ++i) {
    std::array<Dual, 5> qd;
    for (int j = 0; j < 5; ++j) qd[j] = Dual(q[j], i == j ? 1.0 : 0.0);
    basis(qd, b);
    for (int k = 0; k < 17; ++k)
      for (int r = 0; r < 5; ++r)
        for (int c = 0; c < 5; ++c) {
          out.dh[i][k][r][c] = b[k][r][c].d;
          if (i == 0) out.h[k][r][c] = b[k][r][c].v;
        }
  }
}

// C_kj = sum_i 1/2 (dH_kj/dq_i + dH_ki/dq_j - dH_ij/dq_k) q'_i (Eq. C.14), with dh[i] = dH/dq_i.
Matrix5d christoffel(const std::array<Matrix5d, 5>& dh, const Vector5d& qd) {
  Matrix5d c = Matrix5d::Zero();
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 5; ++i)
        c(k, j) += 0.5 * (dh[i](k, j) + dh[j](k, i) - dh[k](i, j)) * qd[i];  // Eq. C.14
  return c;
}

// dH/dq_i of the weighted sum of basis matrices (a = unit vector: one basis matrix).
std::array<Matrix5d, 5> inertia_derivatives(const std::array<Basis<double>, 5>& dh,
                                            const Vector17d& a) {
  std::array<Matrix5d, 5> out;
  for (int i = 0; i < 5; ++i) {
    out[i].setZero();
    for (int k = 0; k < 14; ++k)
      if (a[k] != 0)
        for (int r = 0; r < 5; ++r)
          for (int c = 0; c < 5; ++c) out[i](r, c) += a[k] * dh[i][k][r][c];
  }
  return out;
}

Matrix5d to_matrix(const std::array<std::array<double, 5>, 5>& b) {
  Matrix5d m;
  for (int r = 0; r < 5; ++r)
    for (int c = 0; c < 5; ++c) m(r, c) = b[r][c];
  return m;
}

// Generalised momentum H(q) q' straight from the link velocities w_k = U_k q' (no 5x5 basis):
// the cheap path for forward dynamics.
template <typename T>
std::array<T, 5> momentum(const std::array<T, 5>& q, const Vector5d& qd, const Vector17d& a) {
  Dir<T> u1, u2, u3;
  std::array<T, 3> uz;
  directions(q, u1, u2, u3, uz);
  const Dir<T>* u[3] = {&u1, &u2, &u3};
  std::array<std::array<T, 3>, 3> w;  // w[k] = U_k q'
  for (int k = 0; k < 3; ++k)
    for (int r = 0; r < 3; ++r) {
      T s(0.0);
      for (int c = 0; c < 5; ++c) s += qd[c] * (*u[k])[r][c];
      w[k][r] = s;
    }
  // dK/dq' = sum over the pairs (k, l) weights * U_k^T w_l, plus the rotational rates.
  const double weight[3][3] = {
      {a[0] + a[2] + a[4], a[8], a[6]}, {a[8], a[1] + a[5], a[7]}, {a[6], a[7], a[3]}};
  std::array<T, 5> p;
  for (int c = 0; c < 5; ++c) {
    T s(0.0);
    for (int k = 0; k < 3; ++k)
      for (int l = 0; l < 3; ++l)
        for (int r = 0; r < 3; ++r) s += weight[k][l] * ((*u[k])[r][c] * w[l][r]);
    p[c] = s;
  }
  const double roll1 = qd[0], roll2 = qd[0] + qd[4], pitch1 = qd[1], pitch2 = qd[1] + qd[2],
               pitch3 = qd[1] + qd[2] + qd[3];
  p[0] += T(a[9] * roll1 + a[10] * roll2);
  p[4] += T(a[10] * roll2);
  p[1] += T(a[11] * pitch1 + a[12] * pitch2 + a[13] * pitch3);
  p[2] += T(a[12] * pitch2 + a[13] * pitch3);
  p[3] += T(a[13] * pitch3);
  return p;
}

// C q' = H' q' - dK/dq (Lagrange), both by single dual passes over the momentum / energy.
Vector5d bias(const Vector5d& q, const Vector5d& qd, const Vector17d& a) {
  std::array<Dual, 5> along;
  for (int j = 0; j < 5; ++j) along[j] = Dual(q[j], qd[j]);
  const std::array<Dual, 5> p = momentum(along, qd, a);
  Vector5d b;
  for (int i = 0; i < 5; ++i) {
    std::array<Dual, 5> qi;
    for (int j = 0; j < 5; ++j) qi[j] = Dual(q[j], i == j ? 1.0 : 0.0);
    const std::array<Dual, 5> pi = momentum(qi, qd, a);
    double dk = 0;  // dK/dq_i = 1/2 q'^T (dH/dq_i) q'
    for (int c = 0; c < 5; ++c) dk += 0.5 * qd[c] * pi[c].d;
    b[i] = p[i].d - dk;
  }
  return b;
}

Matrix5d inertia_only(const Vector5d& q, const Vector17d& a) {
  std::array<double, 5> qa;
  for (int i = 0; i < 5; ++i) qa[i] = q[i];
  Basis<double> b;
  basis(qa, b);
  Matrix5d h = Matrix5d::Zero();
  for (int k = 0; k < 14; ++k) h += a[k] * to_matrix(b[k]);
  return h;
}

}  // namespace

Leg3dData thesis_3d_leg() {
  return {0.3897,        0.2914,        0.1618,        0.00163671962, 0.00118207967,
          0.00026944182, 0.00159107278, 0.00112865226, 0.00064434250, 0.1,
          0.1029,        0.04519,       0.0538,        0.0496,        0.0413};
}

Vector17d leg3d_parameters(const Leg3dData& d) {
  Vector17d a;
  a << d.m1 * d.b1 * d.b1, d.m2 * d.b2 * d.b2, d.m2 * d.l1 * d.l1,  // J1..J3
      d.m3 * d.b3 * d.b3, d.m3 * d.l1 * d.l1, d.m3 * d.l2 * d.l2,   // J4..J6
      d.m3 * d.b3 * d.l1, d.m3 * d.b3 * d.l2,                       // J7, J8
      d.m2 * d.l1 * d.b2 + d.m3 * d.l1 * d.l2,                      // J9
      d.ixx1 + d.ixx2, d.ixx3, d.iyy1, d.iyy2, d.iyy3,              // J10..J14
      (d.m1 * d.b1 + d.m2 * d.l1 + d.m3 * d.l1) * d.gravity,        // J15
      (d.m2 * d.b2 + d.m3 * d.l2) * d.gravity,                      // J16
      d.m3 * d.b3 * d.gravity;                                      // J17
  return a;
}

Leg3dTerms leg3d_terms(const Vector5d& q, const Vector5d& qd, const Vector17d& a) {
  BasisWithDerivatives b;
  basis_with_derivatives(q, b);
  std::array<Vector5d, 3> g;
  gravity_basis(q, g);
  Leg3dTerms t{Matrix5d::Zero(), Matrix5d::Zero(), Vector5d::Zero()};
  for (int k = 0; k < 14; ++k)
    if (a[k] != 0) t.inertia += a[k] * to_matrix(b.h[k]);
  t.coriolis = christoffel(inertia_derivatives(b.dh, a), qd);
  for (int k = 0; k < 3; ++k) t.gravity += a[14 + k] * g[k];
  return t;
}

Leg3dRegressor leg3d_regressor(const Vector5d& q, const Vector5d& qd, const Vector5d& qd_r,
                               const Vector5d& qdd_r) {
  BasisWithDerivatives b;
  basis_with_derivatives(q, b);
  std::array<Vector5d, 3> g;
  gravity_basis(q, g);
  Leg3dRegressor y;
  for (int k = 0; k < 14; ++k)
    y.col(k) = to_matrix(b.h[k]) * qdd_r +
               christoffel(inertia_derivatives(b.dh, Vector17d::Unit(k)), qd) * qd_r;
  for (int k = 0; k < 3; ++k) y.col(14 + k) = g[k];
  return y;
}

Vector5d leg3d_coriolis_times_velocity(const Vector5d& q, const Vector5d& qd, const Vector17d& a) {
  return bias(q, qd, a);
}

Vector5d leg3d_forward_dynamics(const Vector5d& q, const Vector5d& qd, const Vector5d& tau,
                                const Vector17d& a) {
  std::array<Vector5d, 3> g;
  gravity_basis(q, g);
  const Vector5d gravity = a[14] * g[0] + a[15] * g[1] + a[16] * g[2];
  return inertia_only(q, a).llt().solve(tau - bias(q, qd, a) - gravity);
}

double leg3d_energy(const Vector5d& q, const Vector5d& qd, const Vector17d& a) {
  const Matrix5d h = inertia_only(q, a);
  std::array<double, 5> qa;
  for (int i = 0; i < 5; ++i) qa[i] = q[i];
  Dir<double> u1, u2, u3;
  std::array<double, 3> uz;
  directions(qa, u1, u2, u3, uz);
  return 0.5 * qd.dot(h * qd) + a[14] * uz[0] + a[15] * uz[1] + a[16] * uz[2];
}

}  // namespace stride::model
