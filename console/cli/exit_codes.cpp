#include "console/cli/exit_codes.hpp"

#include <ostream>
#include <string_view>

namespace stride::cli {

int exit_code(const Error& e) {
  if (dynamic_cast<const UsageError*>(&e)) return kExitUsage;
  if (dynamic_cast<const InputError*>(&e)) return kExitBadInput;
  return kExitRunFailure;
}

int report_error(const Error& e, std::ostream& err, const char* prefix) {
  const std::string_view what = e.what();
  err << (what.starts_with(prefix) ? "" : prefix) << what << "\n";  // reader errors name it
  return exit_code(e);
}

}  // namespace stride::cli
