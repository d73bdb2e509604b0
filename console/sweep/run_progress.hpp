#pragma once
// The progress line of a sweep (console/progress) fed by the engine's callbacks: the engine
// reports once before any run (the resumed ones) and after each run; only the runs made now
// count, so a resumed sweep's rate and ETA are right.
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>

#include "console/progress/progress_line.hpp"

namespace stride::sweep {

class RunProgress {
 public:
  RunProgress(std::ostream& err, std::string label, bool quiet);
  void update(std::size_t done, std::size_t failed, std::size_t total);
  void tick();
  void finish();

 private:
  std::ostream& err_;
  std::string label_;
  console::ProgressSettings settings_;
  std::optional<console::ProgressLine> line_;
  std::size_t done_before_ = 0, failed_before_ = 0;
};

}  // namespace stride::sweep
