#include "console/cli/exit_codes.hpp"

#include <ostream>

namespace stride::cli {

int exit_code(const Error& e) {
  if (dynamic_cast<const UsageError*>(&e)) return kExitUsage;
  if (dynamic_cast<const InputError*>(&e)) return kExitBadInput;
  return kExitRunFailure;
}

int report_error(const Error& e, std::ostream& err, const char* prefix) {
  err << prefix << e.what() << "\n";
  return exit_code(e);
}

}  // namespace stride::cli
