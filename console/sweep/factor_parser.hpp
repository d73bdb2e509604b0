#pragma once
// The parts of a sweep file that say which runs there are: <set>, <factor> with its levels,
// <grid> and <sample> blocks, <seeds>.
#include <cstdint>
#include <vector>

#include "console/sweep/sweep_spec.hpp"
#include "robot/core/xml_element.hpp"

namespace stride::sweep {

// <set target="..." value="..."/>
Setting parse_set(const XmlElement& e);
// <factor name target values|range format> or with <level> children, and per-level <set> and
// <column> templates.
Factor parse_factor(const XmlElement& e);
// <grid> (children <set>, <column>, <factor>) or <sample method count seed> (<set>, <range>).
Block parse_block(const XmlElement& e);
// <range name target min max format>: one continuous range of a <sample> or of <seeds>.
Block::Range parse_range(const XmlElement& e);
// <seeds from to> | <seeds values> | <seeds count>
std::vector<std::uint64_t> parse_seeds(const XmlElement& e);
// The same with the perturbed starts' spreads (heading_spread, position_spread: 0 to 0.5).
struct SeedsElement {
  std::vector<std::uint64_t> seeds;
  double heading_spread = 0, position_spread = 0;  // rad, m
  std::vector<Block::Range> draws;                 // <range> children: one value per seed
};
SeedsElement parse_seeds_element(const XmlElement& e);

// Texts listed in an attribute: split at commas when there is one, otherwise at white space.
std::vector<std::string> split_list(const std::string& text);

}  // namespace stride::sweep
