#pragma once
// Texts with placeholders, for the values a factor level sets: "{}" is the level's own text,
// "{v - 0.005}" an expression over the factor's value (named as the factor), and "{v:.3f}" the
// same printed with a printf conversion (g, e, f with flags, width and precision).
#include <string>

namespace stride::sweep {

// Throws stride::Error naming the placeholder on a bad expression or conversion.
std::string expand_template(const std::string& text, const std::string& name,
                            const std::string& level_text);

}  // namespace stride::sweep
