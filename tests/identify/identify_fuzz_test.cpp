// Replays the identify fuzzer's corpus (tests/fuzz_identify/corpus): every input is accepted or
// refused with a one-line stride::Error, and the seeds that must be accepted are.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/fuzz_identify/identify_fuzz_target.hpp"

namespace stride {
namespace {

namespace fs = std::filesystem;

TEST(IdentifyFuzz, CorpusReplays) {
  int files = 0;
  for (const auto& e : fs::directory_iterator(STRIDE_SOURCE_DIR "/tests/fuzz_identify/corpus")) {
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    const std::string bytes = s.str();
    const std::string what = test::identify_fuzz_input(
        reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    EXPECT_EQ(what.find('\n'), std::string::npos) << e.path() << ": " << what;
    if (e.path().filename().string().starts_with("ok_")) EXPECT_EQ(what, "") << e.path();
    ++files;
  }
  EXPECT_GE(files, 6);
}

}  // namespace
}  // namespace stride
