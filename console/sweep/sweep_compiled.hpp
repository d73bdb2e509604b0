#pragma once
// Inside a Sweep: the names of its spec bound to slots once, shared by the checks (sweep.cpp) and
// the runs (run_execution.cpp).
#include <optional>
#include <string>
#include <vector>

#include "console/sweep/expression.hpp"
#include "console/sweep/sweep.hpp"

namespace stride::sweep {

struct Sweep::Compiled {
  std::vector<std::string> frame_keys;  // per-frame keys, each once
  std::vector<bool> trace_only;         // per frame key: read by traces alone (bound when traced)
  bool walk_frame = false;              // frame.* keys or walk marks need the WalkFrame observer
  struct Summary {
    int key = -1;  // into frame_keys
    std::optional<Expression> until;
  };
  std::vector<Summary> summaries;   // as spec.record.summaries
  std::vector<Expression> derived;  // over the row: plan columns, then record columns
  struct Trace {
    std::optional<Expression> where;  // over the plan columns
    std::vector<int> keys;            // into frame_keys
  };
  std::vector<Trace> traces;
};

// The plan's cells as expression values: a cell that reads entirely as a number is a number.
std::vector<Cell> plan_cells(const RunPlan& run);
// A cell's text as a value of a column: numbers for number columns ("" and "nan" are NaN).
Cell cell_value(const std::string& text, bool text_column);

// The run itself (run_execution.cpp): the record columns' texts; throws on any failure.
std::vector<std::string> execute_run(const Sweep& sweep, const Sweep::Compiled& c,
                                     const RunPlan& run, std::string& trace_csv);

}  // namespace stride::sweep
