#pragma once
// One fuzz input for the tuning-file parser: the text parsed as a tuning file, then a
// generation's sweep and the held-out sweep built from it and compiled (keys, expressions,
// tallies) without loading scenes, as `stride tune` does before its first walk. Any outcome but
// success or a stride::Error is a bug (the caller sees other exceptions).
#include <cstddef>
#include <cstdint>
#include <string>

#include "console/sweep/sweep.hpp"
#include "console/sweep/tally.hpp"
#include "console/tune/tune_parser.hpp"
#include "console/tune/tune_sweeps.hpp"
#include "robot/core/error.hpp"

namespace stride::test {

// Returns the error message, or "" when the input was accepted.
inline std::string tune_fuzz_input(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const tune::TuneSpec spec = tune::parse_tune_text(text, "/nonexistent/fuzz.tune.xml");
    std::vector<double> thesis;
    for (const tune::TuneParam& p : spec.params) thesis.push_back(p.thesis);
    const sweep::Sweep train(tune::batch_spec(spec, {"generation", 0, {"0"}, {thesis}}), false);
    sweep::SweepSpec held =
        tune::batch_spec(spec, {"heldout", 0, {"thesis", "tuned"}, {thesis, thesis}});
    tune::add_heldout_tallies(held, train.record_columns());
    const sweep::Sweep heldout(std::move(held), false);
    const sweep::Tallies tallies(heldout);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace stride::test
