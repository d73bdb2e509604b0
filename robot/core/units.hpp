#pragma once
// Quantities in scene and robot config files: SI by default, or a number followed by a unit of the right kind.
#include <string>
#include <string_view>

namespace stride {

enum class Dimension { None, Length, Angle, Mass, Time, Force, Frequency };

std::string_view dimension_name(Dimension d);

// "0.5", "5mm", "10 deg", "2ms" -> SI value. Throws std::invalid_argument with a message that
// names what was expected (the caller adds file:line and the attribute).
double parse_quantity(std::string_view text, Dimension d);

}  // namespace stride
