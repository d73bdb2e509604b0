// `stride balance <what> ...`: the balance analyses of thesis Ch. 7 from the command line; the
// analyses themselves are console/experiments/balance_analyses.
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "console/cli/arguments.hpp"
#include "console/cli/exit_codes.hpp"
#include "console/cli/subcommand.hpp"
#include "console/experiments/balance_analyses.hpp"
#include "console/output/output_paths.hpp"
#include "console/plot/run_figures.hpp"
#include "robot/core/error.hpp"
#include "robot/core/number_text.hpp"
#include "robot/core/quote.hpp"

namespace stride::cli {

namespace {
using experiments::BalanceAnalysisOptions;

constexpr const char* kUsage =
    "usage: stride balance classify|ankle-boundaries|closed-loop|hip|combined|lqr "
    "[--x0 m] [--v0 m/s] [--kp] [--kd] [--x-set] [--g] [--z] [--mass] [--zmp-min] [--zmp-max] "
    "[--inertia] [--tau-f] [--tau-b] [--theta-max-f] [--theta-max-b] [--theta0] [--theta-dot0] "
    "[--q a,b,c,d] [--r a,b] [--duration s] [--dt s] [--json] [--csv out.csv] [--plots dir]";

struct Options {
  BalanceAnalysisOptions analysis;
  bool json = false;
  std::string csv, plots;
};

std::vector<double> number_list(ArgumentReader& a, const std::string& flag,
                                const std::vector<double>& fallback) {
  if (!a.has(flag)) return fallback;
  const std::string text = a.text(flag);
  std::vector<double> out;
  std::stringstream ss(text);
  try {
    for (std::string item; std::getline(ss, item, ',');)
      out.push_back(stride::parse_number(item, "stride balance: " + flag));
  } catch (const UsageError&) {
    throw;
  } catch (const Error& e) {
    throw UsageError(e.what());  // a malformed number is a wrong command line
  }
  if (out.size() != fallback.size())
    throw UsageError("stride balance: " + flag + " expects " + std::to_string(fallback.size()) +
                     " comma-separated numbers, got " + quote(text));
  return out;
}

void read_model(ArgumentReader& a, balance::BalanceParams& p) {
  for (const auto& [flag, field] : {std::pair{"--g", &p.g},
                                    {"--z", &p.z_cm},
                                    {"--mass", &p.mass},
                                    {"--zmp-min", &p.zmp_min},
                                    {"--zmp-max", &p.zmp_max},
                                    {"--inertia", &p.inertia},
                                    {"--tau-f", &p.tau_forward},
                                    {"--tau-b", &p.tau_backward},
                                    {"--theta-max-f", &p.theta_max_forward},
                                    {"--theta-max-b", &p.theta_max_backward},
                                    {"--theta0", &p.theta0},
                                    {"--theta-dot0", &p.theta_dot0}})
    *field = a.number_or(flag, *field);
}

void check(const BalanceAnalysisOptions& o) {
  balance::validate(o.p);
  if (!(o.dt > 0) || o.dt > 0.1) throw UsageError("--dt expects a step in (0, 0.1] s");
  if (o.duration && (!(*o.duration > 0) || *o.duration > 60))
    throw UsageError("--duration expects a time in (0, 60] s");
  if (o.duration && *o.duration / o.dt > 2e6)
    throw UsageError("--duration / --dt: too many samples");
  if (o.x0.has_value() != o.v0.has_value() && o.what != "classify")
    throw UsageError("--x0 and --v0 go together");
}

Options parse(Args args) {
  if (args.empty()) throw UsageError("missing <what>; " + std::string(kUsage));
  ArgumentReader a(args, "balance");
  Options o;
  BalanceAnalysisOptions& b = o.analysis;
  b.what = a.positional("what");
  if (a.has("--x0")) b.x0 = a.number("--x0");
  if (a.has("--v0")) b.v0 = a.number("--v0");
  if (a.has("--duration")) b.duration = a.number("--duration");
  b.gains.kp = a.number_or("--kp", b.gains.kp);
  b.gains.kd = a.number_or("--kd", b.gains.kd);
  b.x_set = a.number_or("--x-set", b.x_set);
  b.dt = a.number_or("--dt", b.dt);
  read_model(a, b.p);
  b.q = number_list(a, "--q", b.q);
  b.r = number_list(a, "--r", b.r);
  o.csv = a.text_or("--csv", "");
  o.plots = a.text_or("--plots", "");
  o.json = a.flag("--json");
  a.finish();
  try {
    check(b);
  } catch (const Error& e) {  // a bad flag value, e.g. parameters that fail validation
    throw UsageError(e.what());
  }
  return o;
}

void write_files(const Options& o, const experiments::BalanceReport& rep) {
  if (!o.csv.empty()) plot::write_long_csv(rep.set, o.csv);
  if (!o.plots.empty()) {
    console::make_output_dir("--plots", o.plots);
    for (const plot::Figure& f : rep.figures) plot::write_figure(rep.set, f, o.plots);
  }
}

experiments::BalanceReport analyse(const BalanceAnalysisOptions& o) {
  try {
    return experiments::run_balance_analysis(o);
  } catch (const UsageError& e) {
    throw UsageError(std::string(e.what()) + "; " + kUsage);
  }
}

}  // namespace

int balance_main(Args args, std::ostream& out, std::ostream& err) {
  try {
    const Options o = parse(args);
    if (!o.csv.empty()) console::check_output_file("--csv", o.csv);
    if (!o.plots.empty()) console::check_output_dir("--plots", o.plots);
    experiments::BalanceReport rep = analyse(o.analysis);
    write_files(o, rep);
    if (o.json) {
      out << rep.json.end_object().str() << "\n";
    } else {
      out << rep.text.str();
      if (!o.plots.empty()) out << "plots written to " << o.plots << "\n";
    }
    return 0;
  } catch (const Error& e) {
    return report_error(e, err, "stride balance: ");
  }
}

}  // namespace stride::cli
