#include "simulator/scene/mujoco_options.hpp"

#include <string>

namespace stride::sim {
namespace {

// MuJoCo clamps an impedance to [0.0001, 0.9999]; outside that a stated value would not be used.
double impedance(const XmlElement& e, const char* a, double fallback) {
  const double v = e.number_or(a, fallback);
  if (!(v >= 0.0001 && v <= 0.9999)) e.fail_attr(a, "expected an impedance in [0.0001, 0.9999]");
  return v;
}

}  // namespace

void parse_mujoco_options(const XmlElement& e, PhysicsSettings& p) {
  if (p.engine != PhysicsSettings::Engine::Mujoco) {
    for (const char* a : kMujocoOnly)
      if (e.has(a)) e.fail_attr(a, "a MuJoCo setting; it needs engine=\"mujoco\"");
    if (p.solver == PhysicsSettings::Solver::Cg)
      e.fail_attr("solver", "cg is MuJoCo's solver; ODE has exact and iterative");
    return;
  }
  using Cone = PhysicsSettings::Cone;
  p.cone =
      e.choice_or("cone", {"elliptic", "pyramidal"}, 0) == 0 ? Cone::Elliptic : Cone::Pyramidal;
  p.noslip_iterations = e.integer_or("noslip_iterations", p.noslip_iterations, 0, 1000);
  p.contact_timeconst = e.number_or("contact_timeconst", p.contact_timeconst, Dimension::Time);
  // MuJoCo would silently raise a time constant below two steps to two steps (its refsafe).
  if (!(p.contact_timeconst >= 2 * p.step && p.contact_timeconst <= 1))
    e.fail_attr("contact_timeconst",
                "expected a time in [2 steps (" + std::to_string(2 * p.step) + " s), 1 s]");
  p.contact_dampratio = e.number_or("contact_dampratio", p.contact_dampratio);
  if (!(p.contact_dampratio > 0 && p.contact_dampratio <= 100))
    e.fail_attr("contact_dampratio", "expected a damping ratio in (0, 100]");
  p.contact_dmin = impedance(e, "contact_dmin", p.contact_dmin);
  p.contact_dmax = impedance(e, "contact_dmax", p.contact_dmax);
}

}  // namespace stride::sim
