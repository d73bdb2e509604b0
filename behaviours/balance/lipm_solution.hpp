#pragma once
// Closed-form CoM motion of the LIPM xddot - omega^2 x = f with constant forcing f (Eq. 7.12).
#include <array>
#include <functional>

#include "behaviours/balance/balance_params.hpp"

namespace stride::balance {

// State (Eq. 7.12, Eq. 7.15) at time t from s0 under constant f (f = -omega^2 x_zmp for the ankle).
ComState lipm_state(const ComState& s0, double omega, double f, double t);

// Constant forcing that keeps the ZMP at x_zmp (f = -g x_zmp / z).
inline double ankle_forcing(double x_zmp, double omega) {
  return -omega * omega * x_zmp;  // Eq. 7.11
}

// The ZMP (Eq. 7.13) at which the open-loop ankle strategy converges from s0.
inline double converging_zmp(const ComState& s0, double omega) {
  return capture_point(s0, omega);
}

// One classical fourth-order Runge-Kutta step of ydot = rhs(t, y) for a fixed-size state.
template <std::size_t N>
using OdeState = std::array<double, N>;

template <std::size_t N>
OdeState<N> rk4_step(const std::function<OdeState<N>(double, const OdeState<N>&)>& rhs, double t,
                     const OdeState<N>& y, double h) {
  auto axpy = [](const OdeState<N>& a, double s, const OdeState<N>& b) {
    OdeState<N> r;
    for (std::size_t i = 0; i < N; ++i) r[i] = a[i] + s * b[i];
    return r;
  };
  const OdeState<N> k1 = rhs(t, y);
  const OdeState<N> k2 = rhs(t + h / 2, axpy(y, h / 2, k1));
  const OdeState<N> k3 = rhs(t + h / 2, axpy(y, h / 2, k2));
  const OdeState<N> k4 = rhs(t + h, axpy(y, h, k3));
  OdeState<N> r;
  for (std::size_t i = 0; i < N; ++i) r[i] = y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  return r;
}

}  // namespace stride::balance
