// libFuzzer entry for the tuning-file parser (tests/fuzz_support/run_fuzzer.sh tune).
#include "tests/fuzz_tune/tune_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::tune_fuzz_input(data, size);
  return 0;
}
