#include "simulator/world/mujoco/mj_contact_law.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "simulator/world/contact_law.hpp"

namespace stride::sim {
namespace {

// The moving body of a contact with the static scene (bodies welded to the world, as the uneven
// floor's tile blocks are), or -1 (robot-robot, or both static); welded bodies count as one, as
// ODE's rigid body does.
int moving_body(const mjModel* m, const mjContact& c) {
  const int b1 = m->body_weldid[m->geom_bodyid[c.geom1]];
  const int b2 = m->body_weldid[m->geom_bodyid[c.geom2]];
  if ((b1 == 0) == (b2 == 0)) return -1;
  return b1 == 0 ? b2 : b1;
}

void set_row(mjData* d, int row, double r, double k, double b) {
  d->efc_R[row] = r;
  d->efc_D[row] = 1 / r;
  d->efc_KBIP[4 * row] = k;
  d->efc_KBIP[4 * row + 1] = b;
  d->efc_KBIP[4 * row + 2] = 1;  // impedance 1: aref = -B vel - K (pos - margin)
  d->efc_KBIP[4 * row + 3] = 0;
}

}  // namespace

void orient_law_contacts(mjData* d) {
  // The normal only: the friction gets rows of its own (mj_law_friction.hpp).
  for (int i = 0; i < d->ncon; ++i) d->contact[i].dim = 1;
}

void impose_law_rows(const mjModel* m, mjData* d, const ContactLaw& law,
                     std::vector<LawBodyLoad>& load_of_body) {
  const double h = m->opt.timestep;
  load_of_body.assign(m->nbody, LawBodyLoad{});
  for (int i = 0; i < d->ncon; ++i)
    if (const int b = moving_body(m, d->contact[i]); b >= 0 && d->contact[i].efc_address >= 0) {
      ++load_of_body[b].points;
      load_of_body[b].depth += std::max(-d->contact[i].dist, 0.0);
    }
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if (c.efc_address < 0) continue;
    const int b = moving_body(m, c);
    const double share = b >= 0 ? law_point_share(law, -c.dist, load_of_body[b]) : 1.0;
    const ContactSoftness s = law_point_softness(law, share, h);
    set_row(d, c.efc_address, s.cfm / h, s.erp / (h * h), 1 / h);
  }
}

}  // namespace stride::sim
