#pragma once
// A contact as a spring and damper in physical units, turned into ODE's per-step ERP and CFM.
namespace stride::sim {

struct ContactSoftness {
  double erp;
  double cfm;
};

// ODE's soft-constraint mapping for one contact point: stiffness [N/m] and damping [N s/m] at
// time step h [s] give ERP = h k / (h k + c) and CFM = 1 / (h k + c).
inline ContactSoftness contact_softness(double stiffness, double damping, double step) {
  const double d = step * stiffness + damping;
  return {step * stiffness / d, 1.0 / d};
}

// The inverse: the spring and damper a pair of ERP (in (0, 1]) and CFM (> 0) stands for.
inline double contact_stiffness_of(const ContactSoftness& s, double step) {
  return s.erp / (step * s.cfm);
}
inline double contact_damping_of(const ContactSoftness& s) {
  return (1.0 - s.erp) / s.cfm;
}

}  // namespace stride::sim
