// libFuzzer entry for the console execution fuzz target (tests/fuzz_support/run_fuzzer.sh).
#include "tests/fuzz_console/console_exec_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::run_console_fuzz_input(data, size);
  return 0;
}
