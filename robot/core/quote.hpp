#pragma once
// Offending input as an error quotes it: in single quotes, control characters escaped so the
// message stays one line, and at most about 80 characters: a longer text keeps its start and end
// around "..." and says how long it was.
#include <string>
#include <string_view>

namespace stride {

std::string quote(std::string_view text);

}  // namespace stride
