#pragma once
// Under the contact law an uneven floor's tiles stay out of MuJoCo's model: MuJoCo 2.2.2 poses
// every geom and bounds every body each step, a fifth of a walk's step for 1920 tiles that never
// move. The robot's contacts with them are found here instead, as MuJoCo's collision pipeline
// found them with the tiles in the model (tile_blocks.hpp): the pairs its bounding-sphere test
// keeps (from a grid of the tiles, as ODE's static_geom_grid), its own collider on the pair (for a
// box-box pair only to decide that it touches: the points are ODE's, mj_box_contacts.hpp), its
// pair parameters, and its broad phase's order. A tile is held by a probe geom of its patch (a
// static geom that collides with nothing) while it is tested, and the probe stands in for it in
// the contact.
#include <memory>
#include <vector>

#include <mujoco/mujoco.h>

#include "simulator/scene/scene_description.hpp"
#include "simulator/world/mujoco/mj_box_contacts.hpp"
#include "simulator/world/ode/static_geom_grid.hpp"

namespace stride::sim {

// A tile as MuJoCo compiles and poses it (model and data fields of its geom).
struct MjTile {
  mjtNum size[3], xpos[3], xmat[9], rbound, margin, gap;
  mjtNum friction[3], solref[mjNREF], solimp[mjNIMP];
  int priority, contype, conaffinity, condim;
  int block;  // its block's rank: MuJoCo's body order
  int patch;  // which probe holds it
};

class MjTileContacts {
 public:
  // The tiles of `blocks` (block_patch: each block's patch) as MuJoCo poses them: the blocks
  // compiled alone, as write_mjcf writes them for `physics`.
  void set_tiles(const PhysicsSettings& physics, const std::vector<std::vector<StaticBox>>& blocks,
                 const std::vector<int>& block_patch);
  bool empty() const { return tiles_.empty(); }
  const std::vector<MjTile>& tiles() const { return tiles_; }

  // After mj_collision: merges each moving body's contacts with the tiles into d->contact where
  // MuJoCo would have listed them. probes[patch] is that patch's probe geom.
  void add(mjModel* m, mjData* d, const std::vector<int>& probes, OdeBoxBoxContacts& boxes,
           int max_per_pair);

 private:
  struct Candidate {
    int block, geom, tile;
    bool operator<(const Candidate& o) const {
      return block != o.block ? block < o.block : geom != o.geom ? geom < o.geom : tile < o.tile;
    }
  };
  struct Found {
    int body;
    mjContact contact;
  };
  void collide(mjModel* m, mjData* d, int body, int geom, const MjTile& t, int probe,
               OdeBoxBoxContacts& boxes, int max_per_pair);
  void merge(const mjModel* m, mjData* d);

  std::vector<MjTile> tiles_;
  std::unique_ptr<StaticGeomGrid> grid_;  // the tiles' bounding-sphere boxes
  mjtNum max_margin_ = 0;                 // the largest tile margin: the queries' slack
  std::vector<int> ranks_;
  std::vector<Candidate> candidates_;
  std::vector<Found> found_;
  std::vector<mjContact> merged_;
};

}  // namespace stride::sim
