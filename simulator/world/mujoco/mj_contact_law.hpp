#pragma once
// The scene's contact law on MuJoCo: each contact's constraint rows made the rows ODE solves for
// the same law (ode_world.cpp), so the two engines solve one problem. A row of MuJoCo's solution
// obeys J a = aref - R f; ODE's soft contact row J v' = ERP depth / h - CFM f with a = (v' - v) / h
// is that row with R = CFM / h and aref = -(ERP / h^2) (pos - margin) - v / h. Friction rows get
// ODE's world CFM and aim at no slip; a pyramid is ODE's |f_t1|, |f_t2| <= mu f_n (MuJoCo's own is
// |f_u1| + |f_u2|
// <= mu' f_n: the same pyramid turned 45 degrees with mu' = sqrt(2) mu).
#include <vector>

#include <mujoco/mujoco.h>

#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

// Before mj_makeConstraint: every contact's tangents along the law's friction axis (turned for the
// pyramid) and, for the pyramid, its friction scaled to MuJoCo's pyramid; a box-box contact's
// depth measured as ODE's collider measures it.
void orient_law_contacts(const mjModel* m, mjData* d, const ContactLaw& law);

// After mj_makeConstraint, before mj_projectConstraint and mj_referenceConstraint: each contact's
// R, D and reference terms from the law, the body's spring split over its points against the
// static scene (world body 0). `friction_cfm` is ODE's world CFM, which its friction rows take.
void impose_law_rows(const mjModel* m, mjData* d, const ContactLaw& law, double friction_cfm,
                     std::vector<int>& points_per_body);

}  // namespace stride::sim
