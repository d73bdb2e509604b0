#include "console/interpreter/console_plot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace stride::console {

void unwrap_angles(plot::Table& table, const std::vector<std::string>& units) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  for (std::size_t c = 0; c < units.size() && c + 1 < table.columns.size(); ++c) {
    if (units[c] != "rad") continue;
    double offset = 0, previous = std::nan("");
    for (auto& row : table.rows) {
      double& v = row[c + 1];
      if (!std::isfinite(v)) continue;
      if (std::isfinite(previous)) offset -= kTwoPi * std::round((v - previous) / kTwoPi);
      previous = v;
      v += offset;
    }
  }
}

plot::Table decimated(const plot::Table& table, std::size_t max_rows) {
  if (table.rows.size() <= max_rows || max_rows < 2) return table;
  const std::size_t bucket = (table.rows.size() + max_rows / 2 - 1) / (max_rows / 2);
  plot::Table out{table.columns, {}};
  for (std::size_t start = 0; start < table.rows.size(); start += bucket) {
    const std::size_t end = std::min(start + bucket, table.rows.size());
    std::vector<double> low = table.rows[start], high = table.rows[end - 1];
    for (std::size_t c = 1; c < table.columns.size(); ++c) {
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t r = start; r < end; ++r)
        if (const double v = table.rows[r][c]; std::isfinite(v)) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
      low[c] = std::isfinite(lo) ? lo : std::nan("");
      high[c] = std::isfinite(hi) ? hi : std::nan("");
    }
    out.rows.push_back(std::move(low));
    if (end - start > 1) out.rows.push_back(std::move(high));
  }
  return out;
}

std::string legend_label(const std::string& key, std::size_t width) {
  std::string label = key.starts_with("representation:") ? key.substr(15) : key;
  if (label.size() > width) label = "..." + label.substr(label.size() - (width - 3));
  return label;
}

std::string live_summary(const plot::Table& table, std::size_t max_keys) {
  std::ostringstream s;
  s.precision(4);
  s << "plot: " << table.rows.size() << " rows";
  for (std::size_t c = 1; c < table.columns.size() && c <= max_keys; ++c) {
    double lo = INFINITY, hi = -INFINITY, last = std::nan("");
    for (const auto& row : table.rows)
      if (std::isfinite(row[c])) {
        lo = std::min(lo, row[c]);
        hi = std::max(hi, row[c]);
        last = row[c];
      }
    s << "  " << legend_label(table.columns[c]) << " " << last;
    if (std::isfinite(lo)) s << " [" << lo << ", " << hi << "]";
  }
  if (table.columns.size() > max_keys + 1)
    s << "  (+" << table.columns.size() - max_keys - 1 << " more)";
  return s.str();
}

}  // namespace stride::console
