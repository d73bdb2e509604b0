#pragma once
// One error type for every bad input: the message is a single line that says where and what.
#include <stdexcept>
#include <string>

namespace stride {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "file:line: message" — the shape every parser error takes.
inline Error error_at(const std::string& file, int line, const std::string& message) {
  return Error(file + ":" + std::to_string(line) + ": " + message);
}

}  // namespace stride
