#pragma once
// The balance analyses of thesis Ch. 7 as reports: the text, the --json object, the curves and
// the figures of one analysis (classify, ankle-boundaries, closed-loop, hip, combined, lqr), from
// behaviours/balance's models. `stride balance` parses its arguments, calls this and prints.
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "behaviours/balance/ankle_strategy.hpp"
#include "behaviours/balance/balance_params.hpp"
#include "console/plot/run_figures.hpp"
#include "robot/core/json_writer.hpp"

namespace stride::experiments {

struct BalanceAnalysisOptions {
  std::string what;  // classify, ankle-boundaries, closed-loop, hip, combined or lqr
  balance::BalanceParams p;
  std::optional<double> x0, v0;  // one initial state instead of the thesis' cases
  balance::PdGains gains{72, 12};
  double x_set = 0.0;
  std::optional<double> duration;  // s; each analysis has its own default
  double dt = 1e-3;
  std::vector<double> q{2000, 500, 1, 10}, r{4500000, 100};  // Figs. 7.13-7.14
};

struct BalanceReport {
  std::ostringstream text;
  JsonWriter json{JsonWriter::Style::Spaced};  // an open object: the fields of --json
  plot::RunSet set;                            // columns: first is "t"
  std::vector<plot::Figure> figures;
};

// The names `what` takes, for usage lines.
const char* balance_analysis_names();

// Throws stride::UsageError for an unknown `what`.
BalanceReport run_balance_analysis(const BalanceAnalysisOptions& options);

}  // namespace stride::experiments
