// libFuzzer entry for LoLA's packet decoders: tests/fuzz_lola/run_lola_fuzz.sh builds it.
#include "tests/fuzz_lola/lola_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::decode_lola_fuzz_input(data, size);
  return 0;
}
