#include "console/experiments/walk_pool.hpp"

#include <iostream>

#include "console/experiments/recording_codec.hpp"
#include "console/experiments/worker_pool.hpp"
#include "console/progress/progress_line.hpp"

namespace stride::experiments {

void record_walks(const std::vector<WalkSetup>& setups, int jobs,
                  const std::function<bool(std::size_t, WalkRecording&&)>& use,
                  const Failed& failed, const std::string& label) {
  console::ProgressLine progress(std::cerr,
                                 {.label = label,
                                  .total = static_cast<double>(setups.size()),
                                  .unit = "walks",
                                  .failure = "lost"},
                                 console::progress_settings());
  Failed counted;  // a failed walk still advances the progress line, as a lost one
  if (failed)
    counted = [&](std::size_t i, const std::string& reason) {
      progress.advance(1, 1);
      failed(i, reason);
    };
  run_in_workers(
      setups.size(), jobs, [&](std::size_t i) { return encode_recording(record_walk(setups[i])); },
      [&](std::size_t i, std::string&& bytes) {
        WalkRecording r = decode_recording(bytes);
        progress.advance(1, r.metrics.fell || r.metrics.tipped_at >= 0 ? 1 : 0);
        return use(i, std::move(r));
      },
      [&](std::size_t i) {
        return "walk " + setups[i].scene + " (seed " + std::to_string(setups[i].seed) + ")";
      },
      counted);
}

}  // namespace stride::experiments
