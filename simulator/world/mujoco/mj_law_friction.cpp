#include "simulator/world/mujoco/mj_law_friction.hpp"

#include <cstring>
#include <string>

#include <Eigen/Core>

#include "robot/core/error.hpp"
#include "simulator/world/contact_law.hpp"

namespace stride::sim {
namespace {

// Moves rows [from, nefc) of every per-row array mj_makeConstraint wrote `by` rows down (dense
// Jacobian), leaving rows [from, from + by) free.
void shift_rows(const mjModel* m, mjData* d, int from, int by) {
  const int n = d->nefc - from, nv = m->nv;
  const auto move = [&](auto* a, int width) {
    std::memmove(a + (from + by) * width, a + from * width, sizeof(*a) * n * width);
  };
  move(d->efc_type, 1);
  move(d->efc_id, 1);
  move(d->efc_J, nv);
  move(d->efc_pos, 1);
  move(d->efc_margin, 1);
  move(d->efc_frictionloss, 1);
  move(d->efc_diagApprox, 1);
  move(d->efc_KBIP, 4);
  move(d->efc_D, 1);
  move(d->efc_R, 1);
}

// jac = the translational Jacobian of contact c's point on geom2's body minus on geom1's (3 x nv,
// row-major): the velocity of geom2 relative to geom1 there, as MuJoCo's contact rows take it.
void relative_jacobian(const mjModel* m, mjData* d, const mjContact& c, double* jac, double* tmp) {
  const int nv = m->nv;
  mj_jac(m, d, jac, nullptr, c.pos, m->geom_bodyid[c.geom2]);
  mj_jac(m, d, tmp, nullptr, c.pos, m->geom_bodyid[c.geom1]);
  for (int k = 0; k < 3 * nv; ++k) jac[k] -= tmp[k];
}

// The pair's first axis: the law's for the pyramid; for the elliptic cone the slip's (ODE's
// realisation: its pyramid turned to the slip bounds the force against it by mu f_n).
Eigen::Vector3d first_axis(const ContactLaw& law, const Eigen::Vector3d& n,
                           const Eigen::Vector3d& v) {
  if (law.cone == ContactLaw::Cone::Pyramid) return law_friction_axis(n);
  const Eigen::Vector3d slip = v - v.dot(n) * n;
  return slip.norm() > 1e-6 ? Eigen::Vector3d(slip.normalized()) : law_friction_axis(n);
}

void write_row(const mjModel* m, mjData* d, int row, int contact, const Eigen::Vector3d& t,
               const double* jac, double friction_r, double diag) {
  const int nv = m->nv;
  double* j = d->efc_J + row * nv;
  for (int v = 0; v < nv; ++v) j[v] = t[0] * jac[v] + t[1] * jac[nv + v] + t[2] * jac[2 * nv + v];
  d->efc_type[row] = mjCNSTR_FRICTION_TENDON;  // not a dof's: the motors own those rows
  d->efc_id[row] = contact;
  d->efc_pos[row] = 0;
  d->efc_margin[row] = 0;
  d->efc_frictionloss[row] = 0;
  d->efc_diagApprox[row] = diag;
  d->efc_R[row] = friction_r;
  d->efc_D[row] = 1 / friction_r;
  double* kbip = d->efc_KBIP + 4 * row;
  kbip[0] = 0;
  kbip[1] = 1 / m->opt.timestep;  // aref = -v / h: no slip at the end of the step
  kbip[2] = 1;
  kbip[3] = 0;
}

}  // namespace

void insert_law_friction_rows(const mjModel* m, mjData* d, const ContactLaw& law, double friction_r,
                              LawFrictionRows& rows) {
  const int nv = m->nv;
  rows.first = d->ne + d->nf;
  rows.contact.clear();
  rows.mu.clear();
  rows.row_of.assign(d->ncon, -1);
  for (int i = 0; i < d->ncon; ++i)
    if (d->contact[i].efc_address >= 0) rows.contact.push_back(i);
  const int added = 2 * static_cast<int>(rows.contact.size());
  if (added == 0) return;
  if (d->nefc + added > m->njmax)
    throw Error("physics: more constraint rows in one step than mujoco has room for (" +
                std::to_string(m->njmax) +
                " rows, with the contact law's 2 friction rows a contact; bodies piled into "
                "each other or a far too fine floor)");
  shift_rows(m, d, rows.first, added);
  d->nf += added;
  d->nefc += added;
  rows.jac.resize(6 * nv);
  double* jac = rows.jac.data();
  double* tmp = jac + 3 * nv;
  Eigen::Map<const Eigen::VectorXd> qvel(d->qvel, nv);
  for (std::size_t k = 0; k < rows.contact.size(); ++k) {
    const int i = rows.contact[k];
    mjContact& c = d->contact[i];
    c.efc_address += added;
    relative_jacobian(m, d, c, jac, tmp);
    const Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>> jm(jac, 3,
                                                                                         nv);
    const Eigen::Vector3d n(c.frame[0], c.frame[1], c.frame[2]);
    const Eigen::Vector3d t1 = first_axis(law, n, jm * qvel), t2 = n.cross(t1);
    for (int a = 0; a < 3; ++a) {
      c.frame[3 + a] = t1[a];
      c.frame[6 + a] = t2[a];
    }
    const int row = rows.first + 2 * static_cast<int>(k);
    const double diag = d->efc_diagApprox[c.efc_address];
    write_row(m, d, row, i, t1, jac, friction_r, diag);
    write_row(m, d, row + 1, i, t2, jac, friction_r, diag);
    rows.row_of[i] = row;
    rows.mu.push_back(c.friction[0]);
  }
}

bool bound_law_friction(mjData* d, const LawFrictionRows& rows) {
  bool any = false;
  for (std::size_t k = 0; k < rows.contact.size(); ++k) {
    const double fn = d->efc_force[d->contact[rows.contact[k]].efc_address];
    const double bound = fn > 0 ? rows.mu[k] * fn : 0;
    const int row = rows.first + 2 * static_cast<int>(k);
    d->efc_frictionloss[row] = d->efc_frictionloss[row + 1] = bound;
    any = any || bound > 0;
  }
  return any;
}

void law_contact_force(const mjData* d, const LawFrictionRows& rows, int i, double out[3]) {
  out[0] = d->efc_force[d->contact[i].efc_address];
  const int row = i < static_cast<int>(rows.row_of.size()) ? rows.row_of[i] : -1;
  out[1] = row >= 0 ? d->efc_force[row] : 0;
  out[2] = row >= 0 ? d->efc_force[row + 1] : 0;
}

}  // namespace stride::sim
