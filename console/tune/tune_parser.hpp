#pragma once
// Tuning XML -> TuneSpec, with the conventions of sweep files (the same <set>, <seeds>, <run>
// and <record> elements, SI units unless a unit is written, every error one line "file:line:
// <element>: what was expected"). The format is in scenes/experiments/README.md ("tune").
#include <string>

#include "console/tune/tune_spec.hpp"

namespace stride::tune {

TuneSpec parse_tune_file(const std::string& path);
// `text` as if it were the file `virtual_path` (scenes resolve from its directory).
TuneSpec parse_tune_text(const std::string& text, const std::string& virtual_path);

}  // namespace stride::tune
