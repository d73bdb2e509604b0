// libFuzzer entry for the scene and URDF parsers (tests/fuzz_support/run_fuzzer.sh scene).
#include "tests/fuzz_scene/scene_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::parse_fuzz_input(data, size);
  return 0;
}
