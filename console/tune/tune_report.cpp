#include "console/tune/tune_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "console/plot/gnuplot_plot.hpp"

namespace stride::tune {
namespace {

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

std::string line_of(const std::string& name, const CandidateScore& s) {
  return "  " + name + ": " + fixed(s.objective, 4) + " +- " + fixed(s.sd, 4) + " (" +
         std::to_string(s.walks) + " walks, " + std::to_string(s.failed) + " failed)\n";
}

std::string list(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

std::string seed_list(const std::vector<std::uint64_t>& v) {
  if (v.size() > 2 && v.back() - v.front() + 1 == v.size())
    return std::to_string(v.front()) + "-" + std::to_string(v.back());
  std::string s;
  for (std::uint64_t x : v) s += (s.empty() ? "" : " ") + std::to_string(x);
  return s;
}

}  // namespace

std::string report_text(const TuneSpec& t, const TuneResult& r) {
  std::string s = "tune " + t.name + ": " + std::to_string(r.generations) + " generations of " +
                  std::to_string(t.population) + " candidates, " + std::to_string(r.walks) +
                  " training walks (" + std::to_string(r.failed) + " failed); best training " +
                  "objective " + fixed(r.best.score.objective, 4) + " (generation " +
                  std::to_string(r.best.generation) + ", candidate " + r.best.label + ")\n";
  char row[160];
  std::snprintf(row, sizeof row, "  %-20s %12s %12s %12s %8s\n", "parameter", "thesis", "tuned",
                "change", "[%]");
  s += row;
  for (std::size_t p = 0; p < t.params.size(); ++p) {
    const double a = t.params[p].thesis, b = r.best.values.at(p);
    const double change = 100 * (b - a) / std::fabs(a);
    const std::string pct = a != 0 ? (change >= 0 ? "+" : "") + fixed(change, 1) : "-";
    std::snprintf(row, sizeof row, "  %-20s %12.5g %12.5g %+12.5g %8s\n", t.params[p].name.c_str(),
                  a, b, b - a, pct.c_str());
    s += row;
  }
  s += "held-out walks only (floors " + list(t.heldout.floors) + ", seeds " +
       seed_list(t.heldout.seeds) + "), objective mean +- sd over the walks:\n";
  s += line_of("thesis", r.heldout_thesis);
  s += line_of("tuned ", r.heldout_tuned);
  s += "  tuned - thesis: " + fixed(r.heldout_tuned.objective - r.heldout_thesis.objective, 4) +
       "\n";
  return s;
}

void write_tune_plots(const TuneOutput& output, const std::vector<SearchRecord>& records,
                      const TuneResult& result, bool png) {
  png = png && !plot::png_terminal().empty();
  const auto path = [&](const std::string& f) {
    return (std::filesystem::path(output.dir()) / f).string();
  };
  std::map<int, std::vector<double>> by_generation;
  for (const SearchRecord& r : records) by_generation[r.generation].push_back(r.score.objective);
  plot::Table gens{{"generation", "best", "mean", "best_so_far"}};
  double best = -INFINITY;
  for (const auto& [g, v] : by_generation) {
    const double top = *std::max_element(v.begin(), v.end());
    double sum = 0;
    for (double x : v) sum += x;
    best = std::max(best, top);
    gens.add_row({static_cast<double>(g), top, sum / static_cast<double>(v.size()), best});
  }
  plot::write_csv(path("generations.csv"), gens);
  plot::Table walks{{"walk", "thesis", "tuned"}};
  const auto& a = result.heldout_thesis.values;
  const auto& b = result.heldout_tuned.values;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
    walks.add_row({static_cast<double>(k + 1), a[k], b[k]});
  plot::write_csv(path("heldout_walks.csv"), walks);
  if (!png) return;
  plot::PlotSpec search{.csv_path = path("generations.csv"),
                        .x_column = "generation",
                        .series = {{"best", "best of the generation"},
                                   {"mean", "mean of the generation"},
                                   {"best_so_far", "best so far"}},
                        .title = "Objective per generation (training walks)",
                        .x_label = "generation [-]",
                        .y_label = "objective [-]",
                        .png_path = path("search.png")};
  search.style = "linespoints";
  plot::render_png(search);
  plot::PlotSpec held{.csv_path = path("heldout_walks.csv"),
                      .x_column = "walk",
                      .series = {{"thesis", "thesis' parameters"}, {"tuned", "tuned"}},
                      .title = "Held-out walks (floor x seed): objective, thesis against tuned",
                      .x_label = "held-out walk [-]",
                      .y_label = "objective [-]",
                      .png_path = path("heldout.png")};
  held.style = "points";
  held.x_range = "[0.5:" + std::to_string(walks.rows.size()) + ".5]";  // no point on the frame
  plot::render_png(held);
}

}  // namespace stride::tune
