#pragma once
// One error type for every bad input: the message is a single line that says where and what.
// Two refinements say what kind of failure it is, so that every `stride` command exits with the
// same code for the same kind (console/cli/exit_codes.hpp): a wrong command line, or an input
// file or command text that cannot be read or parsed. Any other Error is a run failure.
#include <stdexcept>
#include <string>

namespace stride {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The command line is wrong: unknown subcommand or flag, a missing or malformed value.
class UsageError : public Error {
 public:
  using Error::Error;
};

// A file or command text given to stride cannot be read or parsed (scene, URDF, script, log).
class InputError : public Error {
 public:
  using Error::Error;
};

// "file:line: message" — the shape every parser error takes.
inline Error error_at(const std::string& file, int line, const std::string& message) {
  return Error(file + ":" + std::to_string(line) + ": " + message);
}

// The same for a file that is an input: a scene, URDF or script that does not parse.
inline InputError input_error_at(const std::string& file, int line, const std::string& message) {
  return InputError(file + ":" + std::to_string(line) + ": " + message);
}

// Throws `e` again with "file:line: " in front, keeping its kind.
[[noreturn]] inline void rethrow_at(const std::string& file, int line, const Error& e) {
  const std::string message = file + ":" + std::to_string(line) + ": " + e.what();
  if (dynamic_cast<const UsageError*>(&e)) throw UsageError(message);
  if (dynamic_cast<const InputError*>(&e)) throw InputError(message);
  throw Error(message);
}

}  // namespace stride
