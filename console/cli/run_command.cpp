#include <ostream>

#include "console/cli/subcommand.hpp"

namespace stride::cli {

int run_main(Args args, std::ostream& out, std::ostream& err) {
  err << "stride run: not implemented yet\n";
  return 2;
}

}  // namespace stride::cli
