#pragma once
// The source revision this binary was built from (`git describe --always --dirty`, "unknown"
// outside a git checkout): written into every sweep's manifest so results name their binary.
#include <string_view>

namespace stride::console {

std::string_view build_revision();

}  // namespace stride::console
