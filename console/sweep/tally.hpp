#pragma once
// Tallies over groups of runs: counts, sums, means with standard deviations, extremes, first and
// last values, each over the rows a condition picks, then expressions and texts over those.
// Only runs that ended well enter; a group's failed runs are counted in a `failed` column.
// Sums and means run in run order; the standard deviation is the population one (two passes).
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "console/sweep/expression.hpp"
#include "console/sweep/sweep.hpp"

namespace stride::sweep {

struct TallyTable {
  std::string name, title;
  std::size_t by = 0;                           // how many of the columns group the runs
  std::vector<std::string> columns;             // the `by` columns, then the tally's
  std::vector<bool> hidden;                     // per column: left out of the printed table
  std::vector<std::vector<Cell>> rows;          // one per group
  std::vector<std::vector<double>> sds;         // per row, per column: the sd of a mean (or NaN)
  std::vector<std::vector<std::string>> texts;  // as printed
};

class Tallies {
 public:
  // Compiles every tally's expressions against the sweep's CSV columns; throws stride::Error
  // ("file:line: ..." for sweep files) on an unknown column or bad expression.
  explicit Tallies(const Sweep& sweep);
  ~Tallies();

  // `rows`: the runs so far as CSV cells (Sweep::csv_header() order), in run order.
  std::vector<TallyTable> compute(const std::vector<std::vector<std::string>>& rows) const;

  struct Compiled;

 private:
  const Sweep& sweep_;
  std::vector<std::unique_ptr<Compiled>> tallies_;
};

// The table as fixed-width text: a title line, a header, one line per group.
void print_tally(std::ostream& out, const TallyTable& t);
// Header and rows; means with a standard deviation get a `<name>_sd` column after them.
std::string tally_csv(const TallyTable& t);

}  // namespace stride::sweep
