// libFuzzer entry for LoLA's packet decoders (tests/fuzz_support/run_fuzzer.sh lola).
#include "tests/fuzz_lola/lola_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::decode_lola_fuzz_input(data, size);
  return 0;
}
