// libFuzzer entry for the tuning-file parser: tests/fuzz_tune/run_tune_fuzz.sh builds it.
#include "tests/fuzz_tune/tune_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::tune_fuzz_input(data, size);
  return 0;
}
