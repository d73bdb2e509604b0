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

// The depth of a box-box contact as ODE's collider gives it: along the contact normal through the
// contact point, from the face of one box that faces the other to the other's (MuJoCo 2.2.2's
// box-box collider reports half of it for boxes resting face on face). Only each box's face most
// across the normal bounds it: a point on a box's edge lies on its side faces too, where a slab
// test over all three axes finds an empty interval as soon as the boxes tilt by rounding.
double box_box_depth(const mjModel* m, const mjData* d, const mjContact& c) {
  const Eigen::Vector3d p(c.pos[0], c.pos[1], c.pos[2]), n(c.frame[0], c.frame[1], c.frame[2]);
  double lo = -1e9, hi = 1e9;  // the interval of s with p + s n between both boxes' faces
  for (const int g : {c.geom1, c.geom2}) {
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> r(d->geom_xmat + 9 * g);
    const Eigen::Vector3d o =
        r.transpose() * (p - Eigen::Map<const Eigen::Vector3d>(d->geom_xpos + 3 * g));
    const Eigen::Vector3d dir = r.transpose() * n;
    int k = 0;
    dir.cwiseAbs().maxCoeff(&k);
    const double half = m->geom_size[3 * g + k];
    const double a = (-half - o[k]) / dir[k], b = (half - o[k]) / dir[k];
    lo = std::max(lo, std::min(a, b));
    hi = std::min(hi, std::max(a, b));
  }
  return std::max(0.0, hi - lo);
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

void orient_law_contacts(const mjModel* m, mjData* d) {
  for (int i = 0; i < d->ncon; ++i) {
    mjContact& c = d->contact[i];
    if (m->geom_type[c.geom1] == mjGEOM_BOX && m->geom_type[c.geom2] == mjGEOM_BOX)
      c.dist = -box_box_depth(m, d, c);
    c.dim = 1;  // the normal only: the friction gets rows of its own (mj_law_friction.hpp)
  }
}

void impose_law_rows(const mjModel* m, mjData* d, const ContactLaw& law,
                     std::vector<int>& points_per_body) {
  const double h = m->opt.timestep;
  points_per_body.assign(m->nbody, 0);
  for (int i = 0; i < d->ncon; ++i)
    if (const int b = moving_body(m, d->contact[i]); b >= 0 && d->contact[i].efc_address >= 0)
      ++points_per_body[b];
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    if (c.efc_address < 0) continue;
    const int b = moving_body(m, c);
    const ContactSoftness s = law_point_softness(law, b >= 0 ? points_per_body[b] : 1, h);
    set_row(d, c.efc_address, s.cfm / h, s.erp / (h * h), 1 / h);
  }
}

}  // namespace stride::sim
