#pragma once
// Exit codes: the same kind of failure gives the same code from every `stride` command
// (docs/console.md "Exit codes").
#include <iosfwd>

#include "robot/core/error.hpp"

namespace stride::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRunFailure = 1;  // it ran and failed: an expect, a walk, a step
inline constexpr int kExitUsage = 2;       // the command line is wrong
inline constexpr int kExitBadInput = 3;    // a file or command text cannot be read or parsed

int exit_code(const Error& e);
// Prints the error's line (after `prefix`, e.g. "stride balance: ", unless the line starts with
// it) and returns its exit code.
int report_error(const Error& e, std::ostream& err, const char* prefix = "");

}  // namespace stride::cli
