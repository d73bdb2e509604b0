#include "simulator/world/mujoco/tile_blocks.hpp"

#include <cmath>
#include <map>
#include <utility>

namespace stride::sim {

std::vector<std::vector<StaticBox>> group_tiles(const std::vector<StaticBox>& tiles, double edge) {
  if (tiles.empty()) return {};
  double min_x = INFINITY, min_y = INFINITY;
  for (const StaticBox& t : tiles) {
    min_x = std::min(min_x, t.pose.translation().x());
    min_y = std::min(min_y, t.pose.translation().y());
  }
  std::map<std::pair<long, long>, std::vector<StaticBox>> cells;  // ordered: x-major
  for (const StaticBox& t : tiles) {
    // A tenth of a block's slack keeps centres on a multiple of the edge off a block boundary.
    const long ix = std::lround(std::floor((t.pose.translation().x() - min_x) / edge + 0.1));
    const long iy = std::lround(std::floor((t.pose.translation().y() - min_y) / edge + 0.1));
    cells[{ix, iy}].push_back(t);
  }
  std::vector<std::vector<StaticBox>> blocks;
  blocks.reserve(cells.size());
  for (auto& [cell, block] : cells) blocks.push_back(std::move(block));
  return blocks;
}

std::string mjcf_tile_block_name(std::size_t k) {
  return "tiles" + std::to_string(k);
}

}  // namespace stride::sim
