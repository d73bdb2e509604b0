#pragma once
// The contact law's Coulomb friction on MuJoCo, solved as ODE's exact solver solves it: each
// contact a normal row only (dim 1) and two friction rows of its own in MuJoCo's friction block
// (rows [ne, ne + nf), a box |f| <= bound decoupled from the normal), bounded by mu times the
// normal force of the step's solve without friction. MuJoCo's own friction cones are convex: they
// tie the friction to the normal row, which lifts a sliding contact (mu' |v_t| / h of it); a box
// on separate rows cannot. ODE's Dantzig solver sets its friction bounds the same way: from the
// normal forces it found before it adds the friction rows (lcp.cpp, "the first friction index").
#include <vector>

#include <mujoco/mujoco.h>

#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

// Where the step's friction rows sit: pair k (rows first + 2k, first + 2k + 1) belongs to contact
// contact[k] with coefficient mu[k]; row_of[i] is contact i's first friction row or -1.
struct LawFrictionRows {
  int first = 0;
  std::vector<int> contact, row_of;
  std::vector<double> mu;
  std::vector<double> jac;  // scratch: 2 x 3 x nv translational Jacobians
};

// After mj_makeConstraint with every contact of dim 1 and before mj_projectConstraint: inserts two
// friction rows per contact (first axis the law's for the pyramid, the slip's for the elliptic
// cone, as ODE's), written into the contact's frame rows 2 and 3, at resistance R = friction_r,
// aimed at no slip, bounded by 0 until bound_law_friction. Throws when MuJoCo's rows run out.
void insert_law_friction_rows(const mjModel* m, mjData* d, const ContactLaw& law, double friction_r,
                              LawFrictionRows& rows);

// Each pair's bound: mu times its contact's normal force in efc_force. False when no row has one.
bool bound_law_friction(mjData* d, const LawFrictionRows& rows);

// Contact i's force in its frame (normal, t1, t2) after the solve.
void law_contact_force(const mjData* d, const LawFrictionRows& rows, int i, double out[3]);

}  // namespace stride::sim
