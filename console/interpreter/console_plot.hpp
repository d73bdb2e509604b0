#pragma once
// What `plot stop` draws, made readable: angles unwrapped (no wall of +-pi spikes after a fall),
// long runs decimated to a min/max envelope (a compact .gp, spikes kept), short legend labels.
#include <string>
#include <vector>

#include "console/plot/gnuplot_plot.hpp"

namespace stride::console {

// Unwraps every column whose unit is "rad" (units[i] is column i + 1's; column 0 is time): each
// jump beyond pi becomes continuous. In place.
void unwrap_angles(plot::Table& table, const std::vector<std::string>& units);

// At most about `max_rows` rows: buckets of consecutive rows, each giving two rows (its first
// and last time) with every column's minimum and maximum, so peaks survive. A table that is
// short enough comes back as it is.
plot::Table decimated(const plot::Table& table, std::size_t max_rows);

// A legend label: the key without "representation:", at most `width` characters (the tail kept).
std::string legend_label(const std::string& key, std::size_t width = 36);

// One line for a plot being recorded: rows so far and each key's last value, min and max.
std::string live_summary(const plot::Table& table, std::size_t max_keys = 3);

}  // namespace stride::console
