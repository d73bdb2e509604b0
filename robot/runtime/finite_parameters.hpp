#pragma once
// The rule behind `set module:X ...`: no parameter becomes NaN or infinite through a set. A field
// whose default is NaN (WalkParameters' "from the preset") may take NaN again.
#include <string_view>

#include "robot/framework/value.hpp"

namespace stride {

// Throws stride::Error "<root>.<path>: ..." naming the first double leaf of `after` that is NaN
// or infinite, unless it is NaN where `defaults` is NaN too.
void refuse_nonfinite(const TypeDesc& d, const Value& after, const Value& defaults,
                      std::string_view root);

}  // namespace stride
