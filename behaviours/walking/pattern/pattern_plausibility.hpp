#pragma once
// Parameter sets validate() accepts but no NAO could walk: a 10 ms stride, a 30 cm step, a foot
// lifted 20 cm. They are not refused (a study may probe them on purpose) but flagged, one line
// each, so an absurd value typed by mistake does not pass as a result.
#include <string>
#include <vector>

#include "behaviours/walking/pattern/pattern_parameters.hpp"

namespace stride::walking {

// One note per implausible value, naming it, its value and what a NAO can do; empty if none.
std::vector<std::string> plausibility_notes(const PatternParameters& p);

}  // namespace stride::walking
