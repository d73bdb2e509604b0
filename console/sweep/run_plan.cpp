#include "console/sweep/run_plan.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numeric>
#include <sstream>

#include "robot/core/error.hpp"

namespace stride::sweep {
namespace {

// splitmix64: a fixed generator, so samples are the same on every machine and library.
struct SampleRng {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }
};

class Columns {
 public:
  std::size_t index(const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) return static_cast<std::size_t>(it - names.begin());
    names.push_back(name);
    return names.size() - 1;
  }
  std::vector<std::string> names;
};

// One point of a block before seeds: its settings and column texts.
struct Point {
  std::vector<Setting> settings;
  std::vector<std::pair<std::string, std::string>> cells;
};

std::vector<Point> grid_points(const Block& b) {
  std::vector<Point> points(1);
  for (const Factor& f : b.factors) {
    std::vector<Point> next;
    for (const Point& p : points)
      for (const Level& l : f.levels) {
        Point q = p;
        q.settings.insert(q.settings.end(), l.settings.begin(), l.settings.end());
        q.cells.emplace_back(f.name, l.label);
        q.cells.insert(q.cells.end(), l.columns.begin(), l.columns.end());
        next.push_back(std::move(q));
      }
    points = std::move(next);
  }
  return points;
}

std::vector<Point> sampled_points(const Block& b) {
  SampleRng rng{b.seed};
  const auto n = static_cast<std::size_t>(b.count);
  // u[r][k]: point k's position in range r's [0, 1)
  std::vector<std::vector<double>> u(b.ranges.size(), std::vector<double>(n));
  for (std::size_t r = 0; r < b.ranges.size(); ++r) {
    if (b.kind == Block::Kind::Random) {
      for (double& x : u[r]) x = rng.uniform();
      continue;
    }
    std::vector<std::size_t> strata(n);
    std::iota(strata.begin(), strata.end(), std::size_t{0});
    for (std::size_t i = n; i > 1; --i) std::swap(strata[i - 1], strata[rng.below(i)]);
    for (std::size_t k = 0; k < n; ++k)
      u[r][k] = (static_cast<double>(strata[k]) + rng.uniform()) / static_cast<double>(n);
  }
  std::vector<Point> points(n);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t r = 0; r < b.ranges.size(); ++r) {
      const Block::Range& range = b.ranges[r];
      const double v = range.min + u[r][k] * (range.max - range.min);
      const std::string text = format_value(range.format, v);
      for (const std::string& t : range.targets) points[k].settings.push_back({t, text});
      points[k].cells.emplace_back(range.name, number_text(v));
    }
  return points;
}

// The seed's own draws: a generator of the seed alone (mixed with a constant, so it is not the
// start perturbation's stream), one uniform number per range in order.
Point seed_draws(const std::vector<Block::Range>& ranges, std::uint64_t seed) {
  SampleRng rng{seed ^ 0x2545f4914f6cdd1dULL};
  Point p;
  for (const Block::Range& range : ranges) {
    const double v = range.min + rng.uniform() * (range.max - range.min);
    const std::string text = format_value(range.format, v);
    for (const std::string& t : range.targets) p.settings.push_back({t, text});
    p.cells.emplace_back(range.name, number_text(v));
  }
  return p;
}

}  // namespace

std::string number_text(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

std::string format_value(const std::string& format, double v) {
  std::string out = format;
  const std::string text = number_text(v);
  for (std::size_t at = out.find("{}"); at != std::string::npos; at = out.find("{}", at))
    out.replace(at, 2, text), at += text.size();
  return out;
}

Plan expand(const SweepSpec& spec, std::size_t max_runs) {
  Plan plan;
  Columns columns;
  columns.index("scene");
  std::vector<std::vector<Point>> blocks;
  double total = 0;
  for (const Block& b : spec.blocks) {
    // Counted before the points are built: two factors of 100000 levels are 1e10 points, which
    // would exhaust memory long before the cap below could refuse them.
    double points = b.kind == Block::Kind::Grid ? 1 : b.count;
    if (b.kind == Block::Kind::Grid)
      for (const Factor& f : b.factors) points *= static_cast<double>(f.levels.size());
    total += points * static_cast<double>(spec.seeds.size());
    if (total > static_cast<double>(max_runs)) {
      std::ostringstream why;
      why << "sweep '" << spec.name << "': " << total
          << " runs (levels times seeds), more than the " << max_runs << " a sweep may have";
      throw Error(why.str());
    }
    blocks.push_back(b.kind == Block::Kind::Grid ? grid_points(b) : sampled_points(b));
    for (Point& p : blocks.back()) {
      p.settings.insert(p.settings.begin(), b.settings.begin(), b.settings.end());
      p.cells.insert(p.cells.begin(), b.columns.begin(), b.columns.end());
      for (const auto& [name, text] : p.cells) columns.index(name);
    }
  }
  if (blocks.empty()) blocks.push_back({Point{}});
  const std::size_t seed_column = columns.index("seed");
  for (const Block::Range& r : spec.seed_draws) columns.index(r.name);
  plan.columns = columns.names;
  for (const auto& points : blocks)
    for (const Point& p : points)
      for (std::uint64_t seed : spec.seeds) {
        RunPlan run;
        run.id = static_cast<std::int64_t>(plan.runs.size());
        run.settings = spec.settings;
        run.settings.insert(run.settings.end(), p.settings.begin(), p.settings.end());
        const Point drawn = seed_draws(spec.seed_draws, seed);
        run.settings.insert(run.settings.end(), drawn.settings.begin(), drawn.settings.end());
        run.settings.push_back({"seed", std::to_string(seed)});
        run.cells.assign(plan.columns.size(), "");
        for (const auto& [name, text] : p.cells) run.cells[columns.index(name)] = text;
        for (const auto& [name, text] : drawn.cells) run.cells[columns.index(name)] = text;
        for (const Setting& s : run.settings)
          if (s.target == "scene") run.cells[0] = s.value;
        run.cells[seed_column] = std::to_string(seed);
        plan.runs.push_back(std::move(run));
      }
  if (plan.runs.empty())
    throw Error("sweep '" + spec.name + "': no runs (a factor without levels?)");
  return plan;
}

}  // namespace stride::sweep
