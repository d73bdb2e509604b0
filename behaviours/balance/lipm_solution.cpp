#include "behaviours/balance/lipm_solution.hpp"

#include <cmath>

namespace stride::balance {

ComState lipm_state(const ComState& s0, double omega, double f, double t) {
  const double offset = f / (omega * omega);
  const double c = std::cosh(omega * t);
  const double s = std::sinh(omega * t);
  ComState r;
  r.x = (offset + s0.x) * c + s0.v / omega * s - offset;   // Eq. 7.12
  r.v = omega * ((offset + s0.x) * s + s0.v / omega * c);  // Eq. 7.15
  return r;
}

}  // namespace stride::balance
