#pragma once
// The scene's contact law on MuJoCo: each contact's normal row made the row ODE solves for the
// same law (ode_world.cpp), so the two engines solve one problem. A row of MuJoCo's solution obeys
// J a = aref - R f; ODE's soft contact row J v' = ERP depth / h - CFM f with a = (v' - v) / h is
// that row with R = CFM / h and aref = -(ERP / h^2) (pos - margin) - v / h. The friction has rows
// of its own (mj_law_friction.hpp).
#include <vector>

#include <mujoco/mujoco.h>

#include "simulator/scene/scene_description.hpp"
#include "simulator/world/contact_law.hpp"

namespace stride::sim {

// Before mj_makeConstraint: every contact of dim 1 (its normal).
void orient_law_contacts(mjData* d);

// After mj_makeConstraint: each contact's normal row's R, D and reference terms from the law, the
// body's spring shared over its points against the static scene (world body 0) by their depths.
void impose_law_rows(const mjModel* m, mjData* d, const ContactLaw& law,
                     std::vector<LawBodyLoad>& load_of_body);

}  // namespace stride::sim
