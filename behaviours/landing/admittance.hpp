#pragma once
// Force in, position offset out: a sole (or an ankle) that behaves like the impedance of thesis
// Sec. 6.5 around its planned position, realised by a position-controlled joint. With e = x - x_d
// the offset from the plan and f the measured force beyond the planned one,
//   M e'' + B e' + K e = f    (Eq. 6.13 with x_d'' = 0; M = 0 leaves the quasi-static law 6.17).
// The filter integrates this exactly over one control period, the force held constant in it.
#include <Eigen/Core>

namespace stride::behaviours {

struct Admittance {
  double mass = 0;       // M, kg (or kg m^2 for a rotation); 0: first order (Eq. 6.17)
  double damping = 0;    // B, N s/m (N m s/rad); 0 with M = 0: a pure spring
  double stiffness = 1;  // K, N/m (N m/rad), > 0
};

struct AdmittanceState {
  double offset = 0;  // e, m (rad)
  double rate = 0;    // e', m/s (rad/s)
};

// Where a constant force leaves the offset once it has settled: f / K.
double static_offset(const Admittance& a, double force);

// The discretised model for one (M, B, K, period): x_{k+1} = Phi x_k + Gamma f_k, exact for a
// force held over the period. Throws stride::Error naming the field for a meaningless model.
class AdmittanceFilter {
 public:
  AdmittanceFilter() = default;
  AdmittanceFilter(const Admittance& a, double period);
  AdmittanceState step(const AdmittanceState& s, double force) const;
  const Admittance& model() const { return model_; }
  double period() const { return period_; }

 private:
  Admittance model_;
  double period_ = 0;
  Eigen::Matrix2d phi_ = Eigen::Matrix2d::Identity();
  Eigen::Vector2d gamma_ = Eigen::Vector2d::Zero();
};

}  // namespace stride::behaviours
