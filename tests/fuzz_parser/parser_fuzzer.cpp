// libFuzzer entry for the console's pure parser (tests/fuzz_support/run_fuzzer.sh parser): any text
// must either parse or be rejected with stride::Error; anything else escaping is a crash.
#include <cstddef>
#include <cstdint>
#include <string>

#include "console/interpreter/command_parser.hpp"
#include "console/interpreter/edit_distance.hpp"
#include "console/interpreter/tokenizer.hpp"
#include "console/interpreter/values.hpp"
#include "robot/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    for (const std::string& statement : stride::console::split_statements(text)) {
      try {
        const auto c = stride::console::parse_command(statement);
        if (c.args.size() >= 3)
          stride::console::compare(c.args[0], stride::console::Op::Near, c.args[2], 1e-3);
      } catch (const stride::Error&) {
      }
    }
    stride::console::nearest(text.substr(0, 64), {"help", "run", "log", "expect"});
  } catch (const stride::Error&) {
  }
  return 0;
}
