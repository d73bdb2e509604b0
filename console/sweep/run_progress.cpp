#include "console/sweep/run_progress.hpp"

#include <utility>

namespace stride::sweep {

RunProgress::RunProgress(std::ostream& err, std::string label, bool quiet)
    : err_(err), label_(std::move(label)), settings_(console::progress_settings()) {
  if (quiet) settings_.mode = console::ProgressMode::Quiet;
}

void RunProgress::update(std::size_t done, std::size_t failed, std::size_t total) {
  if (!line_) {
    done_before_ = done, failed_before_ = failed;
    line_.emplace(err_,
                  console::ProgressSpec{.label = label_,
                                        .total = static_cast<double>(total - done),
                                        .unit = "walks",
                                        .failure = "failed"},
                  settings_);
    return;
  }
  line_->set_done(static_cast<double>(done - done_before_), failed - failed_before_);
}

void RunProgress::tick() {
  if (line_) line_->tick();
}

void RunProgress::finish() {
  if (line_) line_->finish();
}

}  // namespace stride::sweep
