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

// The depth of a box-box contact as ODE's collider gives it: the length, along the contact normal
// through the contact point, that lies inside both boxes (MuJoCo 2.2.2's box-box collider reports
// half of it for boxes resting face on face).
double box_box_depth(const mjModel* m, const mjData* d, const mjContact& c) {
  const Eigen::Vector3d p(c.pos[0], c.pos[1], c.pos[2]), n(c.frame[0], c.frame[1], c.frame[2]);
  double lo = -1e9, hi = 1e9;  // the interval of s with p + s n inside both boxes
  for (const int g : {c.geom1, c.geom2}) {
    const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> r(d->geom_xmat + 9 * g);
    const Eigen::Vector3d o =
        r.transpose() * (p - Eigen::Map<const Eigen::Vector3d>(d->geom_xpos + 3 * g));
    const Eigen::Vector3d dir = r.transpose() * n;
    for (int k = 0; k < 3; ++k) {
      const double half = m->geom_size[3 * g + k];
      if (std::abs(dir[k]) < 1e-12) continue;
      const double a = (-half - o[k]) / dir[k], b = (half - o[k]) / dir[k];
      lo = std::max(lo, std::min(a, b));
      hi = std::min(hi, std::max(a, b));
    }
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

void orient_law_contacts(const mjModel* m, mjData* d, const ContactLaw& law) {
  const bool pyramid = law.cone == ContactLaw::Cone::Pyramid;
  for (int i = 0; i < d->ncon; ++i) {
    mjContact& c = d->contact[i];
    if (m->geom_type[c.geom1] == mjGEOM_BOX && m->geom_type[c.geom2] == mjGEOM_BOX)
      c.dist = -box_box_depth(m, d, c);
    const Eigen::Vector3d n(c.frame[0], c.frame[1], c.frame[2]);
    Eigen::Vector3d t1 = law_friction_axis(n);
    Eigen::Vector3d t2 = n.cross(t1);
    if (pyramid) {
      const Eigen::Vector3d u1 = (t1 + t2) / std::sqrt(2.0), u2 = (t2 - t1) / std::sqrt(2.0);
      t1 = u1;
      t2 = u2;
      c.friction[0] *= std::sqrt(2.0);
      c.friction[1] *= std::sqrt(2.0);
    }
    for (int k = 0; k < 3; ++k) {
      c.frame[3 + k] = t1[k];
      c.frame[6 + k] = t2[k];
    }
  }
}

void impose_law_rows(const mjModel* m, mjData* d, const ContactLaw& law, double friction_cfm,
                     std::vector<int>& points_per_body) {
  const double h = m->opt.timestep, friction_r = friction_cfm / h;
  points_per_body.assign(m->nbody, 0);
  for (int i = 0; i < d->ncon; ++i)
    if (const int b = moving_body(m, d->contact[i]); b >= 0 && d->contact[i].efc_address >= 0)
      ++points_per_body[b];
  for (int i = 0; i < d->ncon; ++i) {
    mjContact& c = d->contact[i];
    const int row = c.efc_address;
    if (row < 0) continue;
    const int b = moving_body(m, c);
    const ContactSoftness s = law_point_softness(law, b >= 0 ? points_per_body[b] : 1, h);
    const double normal_r = s.cfm / h, k = s.erp / (h * h), damp = 1 / h;
    const int type = d->efc_type[row];
    if (type == mjCNSTR_CONTACT_PYRAMIDAL) {
      const int edges = 2 * (c.dim - 1);  // their mean is the normal row: each carries edges x R
      for (int e = 0; e < edges; ++e) set_row(d, row + e, edges * normal_r, k, damp);
      c.mu = c.friction[0];
    } else {
      set_row(d, row, normal_r, k, damp);
      if (type == mjCNSTR_CONTACT_ELLIPTIC) {
        for (int j = 1; j < c.dim; ++j) set_row(d, row + j, friction_r, 0, damp);
        c.mu = c.friction[0] * std::sqrt(friction_r / normal_r);  // MuJoCo's regularised cone
      }
    }
  }
}

}  // namespace stride::sim
