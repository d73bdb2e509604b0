#pragma once
// Line-numbered checks of a URDF document before urdfdom sees it (urdfdom reports no lines).
#include <string>

namespace stride::model {

// Throws stride::Error("source:line: ...") for malformed XML, missing joint limits, negative or
// non-finite numbers and mesh collisions.
void validate_urdf_text(const std::string& xml, const std::string& source_name);

}  // namespace stride::model
