#pragma once
// A number as an error message shows it: six significant digits, "1e+300", "0.01", "100000".
#include <sstream>
#include <string>

namespace stride {

inline std::string short_number(double v) {
  std::ostringstream o;
  o.precision(6);
  o << v;
  return o.str();
}

}  // namespace stride
