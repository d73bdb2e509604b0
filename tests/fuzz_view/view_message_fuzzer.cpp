// libFuzzer entry for the view's WebSocket message decoder (tests/fuzz_support/run_fuzzer.sh
// view_message).
#include "tests/fuzz_view/view_fuzz_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  stride::test::fuzz_view_input(data, size);
  return 0;
}
