#include "console/experiments/experiment_options.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "console/output/output_paths.hpp"
#include "console/plot/figure_folder.hpp"
#include "robot/core/data_dir.hpp"
#include "robot/core/error.hpp"

namespace stride::experiments {

std::string scene_path(const ExperimentOptions& o, const std::string& name) {
  // A relative directory not under the working directory is the data directory's (data_dir.hpp).
  const std::string dir = o.scenes_dir.empty() ? o.sweeps_dir : o.scenes_dir;
  const std::filesystem::path p = std::filesystem::path(find_input(dir)) / (name + ".xml");
  std::error_code ec;  // a name the system refuses (too long) is not found either
  if (!std::filesystem::exists(p, ec))
    throw InputError("experiment scene '" + p.string() +
                     "' not found (--scenes <dir> chooses another)");
  return p.string();
}

bool prepare_out_dir(const ExperimentOptions& o) {
  if (o.out_dir.empty()) return false;
  console::make_output_dir("--out", o.out_dir);
  return true;
}

void make_figure_dir(const ExperimentOptions& o, const std::string& folder) {
  if (o.out_dir.empty()) return;
  plot::make_directory((std::filesystem::path(o.out_dir) / folder).string());
}

void write_plot(const ExperimentOptions& o, const plot::Table& table, const std::string& stem,
                const std::string& title, const std::string& x_column,
                const std::vector<plot::Series>& series, const std::string& x_label,
                const std::string& y_label, const std::string& style) {
  write_plot(o, table, stem,
             {.x_column = x_column,
              .series = series,
              .title = title,
              .x_label = x_label,
              .y_label = y_label,
              .style = style});
}

void write_plot(const ExperimentOptions& o, const plot::Table& table, const std::string& stem,
                plot::PlotSpec spec) {
  if (o.out_dir.empty()) return;
  const std::string base = (std::filesystem::path(o.out_dir) / stem).string();
  plot::write_csv(base + ".csv", table);
  if (!o.plots) return;
  spec.csv_path = base + ".csv";
  spec.png_path = base + ".png";
  plot::render_png(spec);
}

void print_table(std::ostream& out, const std::vector<std::string>& header,
                 const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width(header.size());
  for (std::size_t c = 0; c < header.size(); ++c) width[c] = header[c].size();
  for (const auto& r : rows)
    for (std::size_t c = 0; c < r.size() && c < width.size(); ++c)
      width[c] = std::max(width[c], r[c].size());
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c)
      out << (c == 0 ? std::left : std::right) << std::setw(static_cast<int>(width[c])) << cells[c]
          << (c + 1 < cells.size() ? "  " : "");
    out << std::right << "\n";
  };
  line(header);
  for (const auto& r : rows) line(r);
}

std::string fixed(double v, int decimals) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::fixed << std::setprecision(decimals) << v;
  return s.str();
}

}  // namespace stride::experiments
