#include "console/cli/subcommand.hpp"

#include <ostream>

namespace stride::cli {

// Each subcommand lives in its own file; declare it here and add one line to the table.
int run_main(Args args, std::ostream& out, std::ostream& err);

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table = {
      {"run", "run <scene> --seconds S [--seed N] [--report out.json]: headless simulation",
       run_main},
  };
  return table;
}

}  // namespace stride::cli
