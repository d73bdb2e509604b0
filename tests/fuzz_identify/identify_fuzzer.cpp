// libFuzzer entry for `stride identify`'s parsers (tests/fuzz_support/run_fuzzer.sh identify).
#include "tests/fuzz_identify/identify_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::identify_fuzz_input(data, size);
  return 0;
}
