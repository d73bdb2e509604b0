// libFuzzer entry for the debug protocol's decoders (tests/fuzz_support/run_fuzzer.sh debug).
#include "tests/fuzz_debug/debug_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::fuzz_debug_input(data, size);
  return 0;
}
