#include "behaviours/landing/admittance.hpp"

#include <cmath>
#include <string>

#include <unsupported/Eigen/MatrixFunctions>

#include "robot/core/error.hpp"

namespace stride::behaviours {

namespace {
void require(bool ok, const char* field, const char* expected) {
  if (!ok) throw Error(std::string("admittance ") + field + ": expected " + expected);
}
}  // namespace

double static_offset(const Admittance& a, double force) {
  return force / a.stiffness;
}

AdmittanceFilter::AdmittanceFilter(const Admittance& a, double period)
    : model_(a), period_(period) {
  require(std::isfinite(a.mass) && a.mass >= 0, "mass", "a number >= 0");
  require(std::isfinite(a.damping) && a.damping >= 0, "damping", "a number >= 0");
  require(std::isfinite(a.stiffness) && a.stiffness > 0, "stiffness", "a number > 0");
  require(std::isfinite(period) && period > 0, "period", "a time > 0");
  if (a.mass > 0) {
    // [e; e']' = [0 1; -K/M -B/M] [e; e'] + [0; 1/M] f (Eq. 6.13). The exponential of the augmented
    // matrix [A b; 0 0] T holds Phi and Gamma together (zero-order hold on f).
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    m(0, 1) = 1;
    m(1, 0) = -a.stiffness / a.mass;
    m(1, 1) = -a.damping / a.mass;
    m(1, 2) = 1 / a.mass;
    const Eigen::Matrix3d e = (m * period).exp();  // Eq. 6.13, exact over one period
    phi_ = e.topLeftCorner<2, 2>();
    gamma_ = e.topRightCorner<2, 1>();
  } else if (a.damping > 0) {
    // The quasi-static balance B e' + K e = f: first order, time constant B / K.
    const double decay = std::exp(-a.stiffness / a.damping * period);  // Eq. 6.17 with f_e
    phi_ << decay, 0, 0, 0;
    gamma_ << (1 - decay) / a.stiffness, 0;
  } else {
    phi_.setZero();  // a spring alone: e = f / K at once
    gamma_ << 1 / a.stiffness, 0;
  }
}

AdmittanceState AdmittanceFilter::step(const AdmittanceState& s, double force) const {
  const Eigen::Vector2d x = phi_ * Eigen::Vector2d(s.offset, s.rate) + gamma_ * force;
  AdmittanceState out{x(0), x(1)};
  if (!(model_.mass > 0)) out.rate = (out.offset - s.offset) / period_;  // first order: e' seen
  return out;
}

}  // namespace stride::behaviours
