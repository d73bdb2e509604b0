#include "console/experiments/walk_pool.hpp"

#include "console/experiments/recording_codec.hpp"
#include "console/experiments/worker_pool.hpp"

namespace stride::experiments {

void record_walks(const std::vector<WalkSetup>& setups, int jobs,
                  const std::function<bool(std::size_t, WalkRecording&&)>& use) {
  run_in_workers(
      setups.size(), jobs, [&](std::size_t i) { return encode_recording(record_walk(setups[i])); },
      [&](std::size_t i, std::string&& bytes) { return use(i, decode_recording(bytes)); },
      [&](std::size_t i) {
        return "walk " + setups[i].scene + " (seed " + std::to_string(setups[i].seed) + ")";
      });
}

}  // namespace stride::experiments
