#include "console/plot/run_figures.hpp"

#include <algorithm>
#include <cmath>

#include "console/plot/gnuplot_plot.hpp"
#include "robot/core/error.hpp"

namespace stride::plot {

void write_long_csv(const RunSet& set, const std::string& path) {
  Table t;
  t.columns = {"case"};
  t.columns.insert(t.columns.end(), set.columns.begin(), set.columns.end());
  for (std::size_t k = 0; k < set.runs.size(); ++k)
    for (const auto& row : set.runs[k].rows) {
      std::vector<double> r{static_cast<double>(k + 1)};
      r.insert(r.end(), row.begin(), row.end());
      t.add_row(std::move(r));
    }
  write_csv(path, t);
}

void write_figure(const RunSet& set, const Figure& f, const std::string& dir) {
  auto col = [&](const std::string& q) {
    const auto it = std::find(set.columns.begin(), set.columns.end(), q);
    if (it == set.columns.end()) throw Error("figure " + f.stem + ": unknown column '" + q + "'");
    return static_cast<std::size_t>(it - set.columns.begin());
  };
  const bool phase = !f.phase_x.empty();
  std::vector<std::string> qs =
      phase ? std::vector<std::string>{f.phase_x, f.phase_y} : f.quantities;
  for (const FigurePanel& p : f.panels)
    qs.insert(qs.end(), p.quantities.begin(), p.quantities.end());
  std::size_t n = 0;
  for (const Run& r : set.runs) n = std::max(n, r.rows.size());

  Table t;
  PlotSpec spec{dir + "/" + f.stem + ".csv", set.columns.at(0), {}, f.title, f.x_label, f.y_label,
                dir + "/" + f.stem + ".png"};
  spec.x_range = f.x_range;
  spec.y_range = f.y_range;
  spec.references = f.references;
  for (const FigurePanel& p : f.panels) spec.panels.push_back({p.y_label, {}, p.references, ""});
  t.columns.push_back(set.columns.at(0));
  std::vector<std::pair<std::size_t, std::size_t>> picks;  // (run, column)
  double xmin = INFINITY, xmax = -INFINITY;                // finite phase-x span for the lines
  for (std::size_t k = 0; k < set.runs.size(); ++k) {
    const std::string id = "_" + std::to_string(k + 1);
    for (const std::string& q : qs) {
      t.columns.push_back(q + id);
      picks.push_back({k, col(q)});
    }
    const std::string& label = set.runs[k].name;
    if (phase) {
      spec.series.push_back({f.phase_y + id, label, f.phase_x + id});
      for (const auto& row : set.runs[k].rows)
        if (std::isfinite(row[col(f.phase_x)]) && std::abs(row[col(f.phase_x)]) < 1.0) {
          xmin = std::min(xmin, row[col(f.phase_x)]);
          xmax = std::max(xmax, row[col(f.phase_x)]);
        }
    } else if (!f.panels.empty()) {
      for (std::size_t p = 0; p < f.panels.size(); ++p)
        for (const std::string& q : f.panels[p].quantities)
          spec.panels[p].series.push_back(
              {q + id, (f.panels[p].quantities.size() > 1 ? q + " " : "") + label, ""});
    } else {
      for (const std::string& q : qs)
        spec.series.push_back({q + id, (qs.size() > 1 ? q + " " : "") + label, ""});
    }
  }
  if (!std::isfinite(xmin)) xmin = -1, xmax = 1;
  for (const Line& l : f.lines) {
    t.columns.push_back(l.name);
    spec.series.push_back({l.name, l.name, "line_x"});
  }
  if (!f.lines.empty()) t.columns.push_back("line_x");
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> row{NAN};
    for (const auto& [k, c] : picks) {
      const auto& rows = set.runs[k].rows;
      row.push_back(i < rows.size() ? rows[i][c] : NAN);
      if (i < rows.size()) row[0] = rows[i][0];
    }
    const double lx =
        xmin + (xmax - xmin) * i / static_cast<double>(std::max<std::size_t>(1, n - 1));
    for (const Line& l : f.lines) row.push_back(l.slope * lx + l.intercept);
    if (!f.lines.empty()) row.push_back(lx);
    t.add_row(std::move(row));
  }
  write_csv(spec.csv_path, t);
  render_png(spec);
}

}  // namespace stride::plot
