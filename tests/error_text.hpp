#pragma once
// The message of the stride::Error a callable throws, or "" when it throws none.
#include <string>

#include "robot/core/error.hpp"

namespace stride::test_support {

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace stride::test_support
