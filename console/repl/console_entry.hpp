#pragma once
// `stride [scene.xml]` (REPL), `stride --script file.con [scene]`, `stride -c "cmd; cmd" [scene]`.
#include <iosfwd>
#include <string>
#include <vector>

namespace stride::console {

// Returns the process exit code: non-zero when a script command or expect fails.
int console_main(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

std::string console_usage();

}  // namespace stride::console
