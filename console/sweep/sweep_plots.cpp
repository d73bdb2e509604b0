#include "console/sweep/sweep_plots.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numeric>

#include "console/plot/figure_folder.hpp"
#include "console/plot/gnuplot_plot.hpp"
#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

std::size_t column(const TallyTable& t, const std::string& name, const PlotSpec& p,
                   const SweepSpec& spec) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  if (it == t.columns.end())
    throw error_at(spec.file, p.line,
                   "<plot>: tally '" + t.name + "' has no column '" + name + "'");
  return static_cast<std::size_t>(it - t.columns.begin());
}

// The tally rows the plot's `where` keeps, in order (all of them without one).
std::vector<std::size_t> picked_rows(const TallyTable& t, const PlotSpec& p,
                                     const SweepSpec& spec) {
  std::vector<std::size_t> rows(t.rows.size());
  std::iota(rows.begin(), rows.end(), 0);
  if (p.where.empty()) return rows;
  // Checked against the tally's columns when the sweep was loaded (Tallies).
  const Expression where(p.where, [&](std::string_view name) {
    return static_cast<int>(column(t, std::string(name), p, spec));
  });
  std::erase_if(rows, [&](std::size_t r) { return !where.truth(t.rows[r]); });
  return rows;
}

double number(const Cell& c) {
  const double* d = std::get_if<double>(&c);
  return d ? *d : std::numeric_limits<double>::quiet_NaN();
}

// A column name as part of a file name: its unit ("sway[rad]") and anything but letters, digits,
// '-', '_' and '.' left out, so "shake[rad/s]" never names a folder.
std::string file_word(const std::string& column) {
  std::string w;
  for (const char c : column.substr(0, column.find('[')))
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') w += c;
  return w;
}

void write_plot(const SweepSpec& spec, const PlotSpec& p, const TallyTable& t,
                const SweepOutput& output, bool png) {
  const std::size_t x = column(t, p.x, p, spec);
  std::vector<std::size_t> ys;
  for (const std::string& y : p.y) ys.push_back(column(t, y, p, spec));
  const std::vector<std::size_t> picked = picked_rows(t, p, spec);
  // One curve per series value: its rows in tally order, side by side with the other curves'.
  std::vector<std::string> series{""};
  std::vector<std::vector<std::size_t>> members{picked};
  if (!p.series.empty()) {
    const std::size_t s = column(t, p.series, p, spec);
    series.clear(), members.clear();
    for (std::size_t r : picked) {
      const std::string& v = t.texts[r][s];
      auto it = std::find(series.begin(), series.end(), v);
      if (it == series.end()) series.push_back(v), members.emplace_back();
      members[static_cast<std::size_t>(std::find(series.begin(), series.end(), v) - series.begin())]
          .push_back(r);
    }
  }
  plot::Table table;
  std::vector<plot::Series> curves;
  std::size_t longest = 0;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const std::string tag = series[s].empty() ? "" : "[" + series[s] + "]";
    table.columns.push_back(p.x + tag);
    for (std::size_t y = 0; y < ys.size(); ++y) {
      table.columns.push_back(p.y[y] + tag);
      curves.push_back({p.y[y] + tag,
                        p.y[y] + (tag.empty() ? "" : " " + p.series + "=" + series[s]), p.x + tag});
    }
    longest = std::max(longest, members[s].size());
  }
  for (std::size_t k = 0; k < longest; ++k) {
    std::vector<double> row;
    for (const auto& m : members) {
      const bool has = k < m.size();
      row.push_back(has ? number(t.rows[m[k]][x]) : NAN);
      for (std::size_t y : ys) row.push_back(has ? number(t.rows[m[k]][y]) : NAN);
    }
    table.add_row(std::move(row));
  }
  std::string stem = file_word(p.x);
  for (const std::string& y : p.y) stem += "_" + file_word(y);
  const std::string base = plot::figure_stem(output.dir(), t.name, stem);
  plot::write_csv(base + ".csv", table);
  if (!png) return;
  plot::PlotSpec ps{.csv_path = base + ".csv",
                    .x_column = table.columns[0],
                    .series = curves,
                    .title = p.title.empty() ? t.title : p.title,
                    .x_label = p.x_label.empty() ? p.x : p.x_label,
                    .y_label = p.y_label,
                    .png_path = base + ".png"};
  ps.style = "linespoints";
  plot::render_png(ps);
}

}  // namespace

void write_sweep_plots(const SweepSpec& spec, const std::vector<TallyTable>& tallies,
                       const SweepOutput& output, bool png) {
  for (const PlotSpec& p : spec.plots) {
    const auto it = std::find_if(tallies.begin(), tallies.end(),
                                 [&](const TallyTable& t) { return t.name == p.tally; });
    if (it == tallies.end())
      throw error_at(spec.file, p.line, "<plot>: no tally named '" + p.tally + "'");
    write_plot(spec, p, *it, output, png && !plot::png_terminal().empty());
  }
}

}  // namespace stride::sweep
