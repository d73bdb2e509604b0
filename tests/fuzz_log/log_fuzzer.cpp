// libFuzzer entry for the log reader (tests/fuzz_support/run_fuzzer.sh log).
#include "tests/fuzz_log/log_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::read_log_fuzz_input(data, size);
  return 0;
}
