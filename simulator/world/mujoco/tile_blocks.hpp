#pragma once
// MuJoCo 2.2.2 tests every geom of the world body against every body, each step: an uneven
// floor's 1920 tiles as world geoms cost 1920 bounding-sphere tests per robot body. Grouped into
// static bodies of nearby tiles, its sweep-and-prune keeps only the blocks a body's box overlaps.
#include <string>
#include <vector>

#include "simulator/scene/scene_description.hpp"

namespace stride::sim {

// Tiles grouped into square blocks of `edge` metres by their centres: blocks in x-major order,
// tiles within a block in their given order; every tile lands in exactly one block.
std::vector<std::vector<StaticBox>> group_tiles(const std::vector<StaticBox>& tiles, double edge);

// The edge used for MuJoCo's blocks: about 5 x 5 tiles of the 5 cm floor, so a foot's box
// overlaps a few blocks of a few dozen tiles.
constexpr double kTileBlockEdge = 0.25;

// MJCF name of tile block `k`.
std::string mjcf_tile_block_name(std::size_t k);

}  // namespace stride::sim
