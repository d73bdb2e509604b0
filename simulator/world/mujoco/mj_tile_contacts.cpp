#include "simulator/world/mujoco/mj_tile_contacts.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include <Eigen/Geometry>

#include "robot/core/error.hpp"
#include "simulator/world/mujoco/mjcf_writer.hpp"

namespace stride::sim {
namespace {

// A contact's pair parameters as MuJoCo 2.2.2's mj_collideGeoms sets them for geoms of different
// priority: the higher one's condim, friction (unpacked to 5), solref and solimp.
void set_pair_parameters(const mjModel* m, int geom, const MjTile& t, mjtNum margin, mjtNum gap,
                         mjContact& c) {
  const bool robot_wins = m->geom_priority[geom] > t.priority;
  if (m->geom_priority[geom] == t.priority)
    throw Error(
        "mujoco: a robot geom and a floor tile of the same priority (the scene writer "
        "gives them different ones)");
  const mjtNum* fr = robot_wins ? m->geom_friction + 3 * geom : t.friction;
  const mjtNum* ref = robot_wins ? m->geom_solref + mjNREF * geom : t.solref;
  const mjtNum* imp = robot_wins ? m->geom_solimp + mjNIMP * geom : t.solimp;
  c.dim = robot_wins ? m->geom_condim[geom] : t.condim;
  const mjtNum f5[5] = {fr[0], fr[0], fr[1], fr[2], fr[2]};
  std::copy(f5, f5 + 5, c.friction);
  std::copy(ref, ref + mjNREF, c.solref);
  std::copy(imp, imp + mjNIMP, c.solimp);
  c.includemargin = margin - gap;
  c.exclude = c.dist < c.includemargin ? 0 : 1;
  c.efc_address = -1;
  c.mu = 0;
  std::fill(c.H, c.H + 36, 0.0);
}

// The frame mj_collideGeoms completes: the collider's normal normalised once more (which can move
// its last bit), then two tangents (the law writes its own axes there).
void complete_frame(mjContact& c) {
  mju_normalize3(c.frame);
  const Eigen::Vector3d n(c.frame[0], c.frame[1], c.frame[2]);
  const Eigen::Vector3d t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  for (int k = 0; k < 3; ++k) {
    c.frame[3 + k] = t1[k];
    c.frame[6 + k] = t2[k];
  }
}

void hold_in_probe(mjModel* m, mjData* d, int probe, const MjTile& t) {
  std::copy(t.size, t.size + 3, m->geom_size + 3 * probe);
  m->geom_rbound[probe] = t.rbound;
  std::copy(t.xpos, t.xpos + 3, d->geom_xpos + 3 * probe);
  std::copy(t.xmat, t.xmat + 9, d->geom_xmat + 9 * probe);
}

}  // namespace

void MjTileContacts::set_tiles(const PhysicsSettings& physics,
                               const std::vector<std::vector<StaticBox>>& blocks,
                               const std::vector<int>& block_patch) {
  tiles_.clear();
  grid_.reset();
  if (blocks.empty()) return;
  std::vector<GeomInfo> geoms;
  mjModel* m = load_mjcf(write_mjcf(physics, GroundSettings{false, 0}, {}, blocks, {}, geoms));
  mjData* d = mj_makeData(m);
  mj_kinematics(m, d);
  std::vector<Aabb> boxes;
  int g = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (std::size_t k = 0; k < blocks[b].size(); ++k, ++g) {
      MjTile t{};
      std::copy(m->geom_size + 3 * g, m->geom_size + 3 * g + 3, t.size);
      std::copy(d->geom_xpos + 3 * g, d->geom_xpos + 3 * g + 3, t.xpos);
      std::copy(d->geom_xmat + 9 * g, d->geom_xmat + 9 * g + 9, t.xmat);
      std::copy(m->geom_friction + 3 * g, m->geom_friction + 3 * g + 3, t.friction);
      std::copy(m->geom_solref + mjNREF * g, m->geom_solref + mjNREF * (g + 1), t.solref);
      std::copy(m->geom_solimp + mjNIMP * g, m->geom_solimp + mjNIMP * (g + 1), t.solimp);
      t.rbound = m->geom_rbound[g];
      t.margin = m->geom_margin[g];
      t.gap = m->geom_gap[g];
      t.priority = m->geom_priority[g];
      t.contype = m->geom_contype[g];
      t.conaffinity = m->geom_conaffinity[g];
      t.condim = m->geom_condim[g];
      t.block = static_cast<int>(b);
      t.patch = block_patch[b];
      max_margin_ = std::max(max_margin_, t.margin);
      boxes.push_back({t.xpos[0] - t.rbound, t.xpos[0] + t.rbound, t.xpos[1] - t.rbound,
                       t.xpos[1] + t.rbound, t.xpos[2] - t.rbound, t.xpos[2] + t.rbound});
      tiles_.push_back(t);
    }
  mj_deleteData(d);
  mj_deleteModel(m);
  grid_ = std::make_unique<StaticGeomGrid>(std::move(boxes));
}

// MuJoCo's broad phase lists body pairs by (lower body, higher body), each pair's geoms in model
// order; the tiles' bodies come after every robot body, so a body's tile contacts follow all of
// its other contacts, block by block, its geoms in order, each block's tiles in order.
void MjTileContacts::add(mjModel* m, mjData* d, const std::vector<int>& probes,
                         OdeBoxBoxContacts& boxes, int max_per_pair) {
  if (tiles_.empty()) return;
  found_.clear();
  for (int b = 1; b < m->nbody; ++b) {
    if (m->body_weldid[b] == 0) continue;  // static: MuJoCo pairs no welded body with the tiles
    candidates_.clear();
    for (int g = m->body_geomadr[b]; g < m->body_geomadr[b] + m->body_geomnum[b]; ++g) {
      if (m->geom_rbound[g] <= 0) continue;  // a plane: robots have none
      // A cube around the geom's bounding sphere, widened by a margin: it meets the cube of
      // every tile whose sphere it meets.
      const mjtNum r = m->geom_rbound[g] + std::max(m->geom_margin[g], max_margin_) + 1e-9;
      const mjtNum* p = d->geom_xpos + 3 * g;
      const Aabb box = {p[0] - r, p[0] + r, p[1] - r, p[1] + r, p[2] - r, p[2] + r};
      grid_->overlapping_ranks(box.data(), ranks_);
      for (int k : ranks_) candidates_.push_back({tiles_[k].block, g, k});
    }
    std::sort(candidates_.begin(), candidates_.end());
    for (const Candidate& c : candidates_)
      collide(m, d, b, c.geom, tiles_[c.tile], probes[tiles_[c.tile].patch], boxes, max_per_pair);
  }
  merge(m, d);
}

// One robot geom against one tile, as mj_collideGeoms tests a pair (its contype filter and
// bounding spheres, then the pair's collider).
void MjTileContacts::collide(mjModel* m, mjData* d, int body, int geom, const MjTile& t, int probe,
                             OdeBoxBoxContacts& boxes, int max_per_pair) {
  if (!(m->geom_contype[geom] & t.conaffinity) && !(t.contype & m->geom_conaffinity[geom])) return;
  const mjtNum margin = std::max(m->geom_margin[geom], t.margin);
  const mjtNum gap = std::max(m->geom_gap[geom], t.gap);
  const mjtNum* p = d->geom_xpos + 3 * geom;
  const mjtNum dif[3] = {p[0] - t.xpos[0], p[1] - t.xpos[1], p[2] - t.xpos[2]};
  const mjtNum bound = m->geom_rbound[geom] + t.rbound + margin;
  if (dif[0] * dif[0] + dif[1] * dif[1] + dif[2] * dif[2] > bound * bound) return;
  hold_in_probe(m, d, probe, t);
  // mj_collideGeoms orders a pair's geoms by type.
  const bool robot_first = m->geom_type[geom] <= mjGEOM_BOX;
  const int g1 = robot_first ? geom : probe, g2 = robot_first ? probe : geom;
  const mjfCollision collider = mjCOLLISIONFUNC[m->geom_type[g1]][m->geom_type[g2]];
  if (!collider) return;
  mjContact con[mjMAXCONPAIR];
  const int num = collider(m, d, con, g1, g2, margin);
  if (num <= 0) return;
  for (int i = 0; i < num; ++i) {
    con[i].geom1 = g1;
    con[i].geom2 = g2;
    set_pair_parameters(m, geom, t, margin, gap, con[i]);
  }
  if (m->geom_type[geom] == mjGEOM_BOX) {  // its points are ODE's box-box collider's
    mjContact ode[64];
    const int n = boxes.collide(m, d, con[0], max_per_pair, ode);
    for (int k = 0; k < n; ++k) found_.push_back({body, ode[k]});
    return;
  }
  for (int i = 0; i < num; ++i) {
    complete_frame(con[i]);
    found_.push_back({body, con[i]});
  }
}

void MjTileContacts::merge(const mjModel* m, mjData* d) {
  if (found_.empty()) return;
  if (d->ncon + static_cast<int>(found_.size()) > m->nconmax)
    throw Error("physics: more contacts in one step than mujoco has room for (" +
                std::to_string(m->nconmax) + "; bodies piled into each other)");
  merged_.clear();
  std::size_t j = 0;
  for (int i = 0; i < d->ncon; ++i) {
    const mjContact& c = d->contact[i];
    const int lower = std::min(m->geom_bodyid[c.geom1], m->geom_bodyid[c.geom2]);
    while (j < found_.size() && found_[j].body < lower) merged_.push_back(found_[j++].contact);
    merged_.push_back(c);
  }
  while (j < found_.size()) merged_.push_back(found_[j++].contact);
  std::copy(merged_.begin(), merged_.end(), d->contact);
  d->ncon = static_cast<int>(merged_.size());
}

}  // namespace stride::sim
