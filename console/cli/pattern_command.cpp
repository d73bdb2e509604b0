// `stride pattern`: the thesis' walking pattern (Ch. 3) sampled offline to CSV and plots.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "behaviours/walking/pattern/support_polygon.hpp"
#include "behaviours/walking/pattern/walking_pattern.hpp"
#include "console/cli/subcommand.hpp"
#include "robot/core/error.hpp"

namespace stride::cli {

namespace {

using walking::PatternSample;

struct PatternOptions {
  walking::PatternParameters params;
  bool conventional = false;
  double dt = 0.01;  // control period of the thesis (Sec. 3.6: 100 Hz)
  std::string csv, plots;
};

constexpr const char* kUsage =
    "usage: stride pattern [--preset slow|medium|fast|fig3.14|fig3.16] [--set name=value ...] "
    "[--conventional] [--dt s] --csv out.csv [--plots dir]";

double parse_period(const std::string& text) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(v > 0.0) || !std::isfinite(v))
    throw Error("--dt: expected a period > 0 s, got '" + text + "'");
  return v;
}

PatternOptions parse_options(Args args) {
  PatternOptions o;
  std::vector<std::pair<std::string, std::string>> sets;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw Error(a + ": missing value");
      return args[++i];
    };
    if (a == "--preset") {
      o.params = walking::preset(value());
    } else if (a == "--set") {
      const std::string& kv = value();
      const std::size_t eq = kv.find('=');
      if (eq == std::string::npos) throw Error("--set: expected name=value, got '" + kv + "'");
      sets.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
    } else if (a == "--conventional") {
      o.conventional = true;
    } else if (a == "--dt") {
      o.dt = parse_period(value());
    } else if (a == "--csv") {
      o.csv = value();
    } else if (a == "--plots") {
      o.plots = value();
    } else {
      throw Error("unknown argument '" + a + "'");
    }
  }
  // Step counts derive their levels from V_min/V_max, so they are applied last.
  auto is_count = [](const auto& kv) {
    return kv.first.ends_with("_steps") && kv.first != "steps";
  };
  std::stable_partition(sets.begin(), sets.end(), [&](const auto& kv) { return !is_count(kv); });
  for (const auto& [name, val] : sets) walking::set_parameter(o.params, name, val);
  walking::validate(o.params);
  if (o.csv.empty() && o.plots.empty()) throw Error("nothing to write: give --csv and/or --plots");
  return o;
}

}  // namespace

int pattern_main(Args args, std::ostream& out, std::ostream& err) {
  if (args.empty()) {
    err << kUsage << "\n";
    return 2;
  }
  PatternOptions o;
  std::vector<PatternSample> walk;
  try {
    o = parse_options(args);
    walk = o.conventional ? walking::sample_walk(walking::ConventionalPattern(o.params), o.dt)
                          : walking::sample_walk(walking::StretchedKneePattern(o.params), o.dt);
  } catch (const Error& e) {
    err << "stride pattern: " << e.what() << "\n";
    return 2;
  }
  if (!o.csv.empty()) {
    std::ofstream f(o.csv);
    if (!f) {
      err << "stride pattern: cannot write " << o.csv << "\n";
      return 1;
    }
    f << "time,waist_x,waist_y,waist_z,left_x,left_y,left_z,right_x,right_y,right_z,zmp_x,zmp_y,"
         "support\n";
    f.precision(9);
    for (const PatternSample& s : walk) {
      f << s.t << ',' << s.waist.x() << ',' << s.waist.y() << ',' << s.waist.z() << ','
        << s.left_foot.x() << ',' << s.left_foot.y() << ',' << s.left_foot.z() << ','
        << s.right_foot.x() << ',' << s.right_foot.y() << ',' << s.right_foot.z() << ','
        << s.zmp.x() << ',' << s.zmp.y() << ',' << static_cast<int>(s.support) << '\n';
    }
  }
  double worst = std::numeric_limits<double>::infinity();
  for (const PatternSample& s : walk)
    worst = std::min(worst, walking::inside_margin(walking::support_polygon(s), s.zmp));
  const double duration = walk.back().t, distance = walk.back().waist.x();
  out << (o.conventional ? "conventional" : "stretched-knee") << " pattern: " << o.params.steps + 1
      << " foot steps in " << duration << " s, " << distance << " m, " << distance / duration
      << " m/s mean, step length " << distance / (o.params.steps + 1)
      << " m (distance / steps), worst ZMP margin to the support polygon " << worst << " m\n";
  return 0;
}

}  // namespace stride::cli
