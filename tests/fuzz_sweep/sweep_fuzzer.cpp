// libFuzzer entry for the sweep engine's decoders (tests/fuzz_support/run_fuzzer.sh sweep).
#include "tests/fuzz_sweep/sweep_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::sweep_fuzz_input(data, size);
  return 0;
}
