#pragma once
// Swing-leg joint controllers of thesis Ch. 5: the Slotine-Li adaptive law and the PD law it is
// compared with. Free functions over a joint count N and a parameter count P, so the planar
// (3 joints, 9 parameters) and 3-D (5 joints, 17 parameters) models share them.
#include <Eigen/Core>

namespace stride::swing_leg {

template <int N>
using JointVector = Eigen::Matrix<double, N, 1>;

template <int N>
struct JointReference {
  JointVector<N> q, qd, qdd;  // desired position, velocity, acceleration
};

template <int P>
struct AdaptiveGains {
  Eigen::Matrix<double, P, 1> gamma;  // adaptation weights, diagonal of Gamma
  double lambda = 200;                // Lambda = lambda I
  double kd = 100;                    // K_D = kd I
};

// The velocity error s and the reference motion it is measured against.
template <int N>
struct SlidingTerms {
  JointVector<N> s, qd_r, qdd_r;
};

// q~ = q - q_d, q'_r = q'_d - Lambda q~, and s = q' - q'_r (Eq. 5.3); q''_r follows by
// differentiating q'_r.
template <int N>
SlidingTerms<N> sliding_terms(const JointVector<N>& q, const JointVector<N>& qd,
                              const JointReference<N>& ref, double lambda) {
  SlidingTerms<N> t;
  t.qd_r = ref.qd - lambda * (q - ref.q);
  t.qdd_r = ref.qdd - lambda * (qd - ref.qd);
  t.s = qd - t.qd_r;  // Eq. 5.3
  return t;
}

// tau = Y a^ - K_D s (Eq. 5.1, Eq. 5.2, Eq. 5.5), with Y = Y(q, q', q'_r, q''_r) of Eq. 5.4.
template <int N, int P>
JointVector<N> adaptive_torque(const Eigen::Matrix<double, N, P>& y,
                               const Eigen::Matrix<double, P, 1>& a_hat, const SlidingTerms<N>& t,
                               double kd) {
  // Eq. 5.5 in Y a^
  // Eq. 5.1: tau = tau^ - K_D s
  return y * a_hat - kd * t.s;
}

// a^' = -Gamma Y^T s.
template <int N, int P>
Eigen::Matrix<double, P, 1> adaptation_rate(const Eigen::Matrix<double, N, P>& y,
                                            const SlidingTerms<N>& t,
                                            const Eigen::Matrix<double, P, 1>& gamma) {
  return -(gamma.asDiagonal() * (y.transpose() * t.s));  // Eq. 5.6
}

// tau = -K_P q~ - K_D q~' (Eq. 5.14) with the gains equivalent to -K_D s: K_P = Lambda K_D
// (Eq. 5.15).
template <int N>
JointVector<N> pd_torque(const JointVector<N>& q, const JointVector<N>& qd,
                         const JointReference<N>& ref, double lambda, double kd) {
  return -lambda * kd * (q - ref.q) - kd * (qd - ref.qd);  // Eq. 5.14 with Eq. 5.15's K_P
}

}  // namespace stride::swing_leg
