// libFuzzer entry for the physics fuzz target (tests/fuzz_support/run_fuzzer.sh physics).
#include "tests/fuzz_physics/physics_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::run_physics_fuzz_input(data, size);
  return 0;
}
