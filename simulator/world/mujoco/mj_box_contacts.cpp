#include "simulator/world/mujoco/mj_box_contacts.hpp"

#include <algorithm>

#include <Eigen/Geometry>

#include "robot/core/error.hpp"
#include "simulator/world/ode/ode_context.hpp"

namespace stride::sim {
namespace {

bool box_box(const mjModel* m, const mjContact& c) {
  return m->geom_type[c.geom1] == mjGEOM_BOX && m->geom_type[c.geom2] == mjGEOM_BOX;
}

// MuJoCo's frame for a normal: the normal, then any two tangents (the law sets its own axes).
void set_frame(mjContact& c, const Eigen::Vector3d& n) {
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  for (int k = 0; k < 3; ++k) {
    c.frame[k] = n[k];
    c.frame[3 + k] = t1[k];
    c.frame[6 + k] = t2[k];
  }
}

}  // namespace

OdeBoxBoxContacts::OdeBoxBoxContacts() {
  ensure_ode_initialised();
  a_ = dCreateBox(nullptr, 1, 1, 1);
  b_ = dCreateBox(nullptr, 1, 1, 1);
}

OdeBoxBoxContacts::~OdeBoxBoxContacts() {
  dGeomDestroy(a_);
  dGeomDestroy(b_);
}

void OdeBoxBoxContacts::place(dGeomID g, const mjModel* m, const mjData* d, int geom) {
  const mjtNum* s = m->geom_size + 3 * geom;
  dGeomBoxSetLengths(g, 2 * s[0], 2 * s[1], 2 * s[2]);
  const mjtNum* p = d->geom_xpos + 3 * geom;
  dGeomSetPosition(g, p[0], p[1], p[2]);
  dMatrix3 r;
  const mjtNum* x = d->geom_xmat + 9 * geom;  // row-major 3 x 3
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r[4 * i + j] = x[3 * i + j];
    r[4 * i + 3] = 0;
  }
  dGeomSetRotation(g, r);
}

int OdeBoxBoxContacts::collide(const mjModel* m, const mjData* d, const mjContact& pair,
                               int max_per_pair, mjContact* out) {
  place(a_, m, d, pair.geom1);
  place(b_, m, d, pair.geom2);
  dContactGeom found[64];
  const int n = dCollide(a_, b_, std::clamp(max_per_pair, 1, 64), found, sizeof(dContactGeom));
  for (int k = 0; k < n; ++k) {
    out[k] = pair;
    out[k].dist = -found[k].depth;
    for (int a = 0; a < 3; ++a) out[k].pos[a] = found[k].pos[a];
    // ODE's normal pushes its first geom away from the second; MuJoCo's points from geom1 to
    // geom2.
    set_frame(out[k], -Eigen::Vector3d(found[k].normal[0], found[k].normal[1], found[k].normal[2]));
  }
  return n;
}

void OdeBoxBoxContacts::replace(const mjModel* m, mjData* d, int max_per_pair) {
  kept_.assign(d->contact, d->contact + d->ncon);
  d->ncon = 0;
  mjContact found[64];
  for (std::size_t i = 0; i < kept_.size(); ++i) {
    const mjContact& c = kept_[i];
    if (!box_box(m, c)) {
      d->contact[d->ncon++] = c;
      continue;
    }
    // One pair's contacts follow each other in MuJoCo's list: collide it at its first.
    if (i > 0 && box_box(m, kept_[i - 1]) && kept_[i - 1].geom1 == c.geom1 &&
        kept_[i - 1].geom2 == c.geom2)
      continue;
    const int n = collide(m, d, c, max_per_pair, found);
    if (d->ncon + n > m->nconmax)
      throw Error("physics: more contacts in one step than mujoco has room for (" +
                  std::to_string(m->nconmax) + "; bodies piled into each other)");
    std::copy(found, found + n, d->contact + d->ncon);
    d->ncon += n;
  }
}

}  // namespace stride::sim
