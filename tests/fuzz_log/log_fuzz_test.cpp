// The log reader under damaged and hostile bytes in every (sanitized) test run: the corpus (an
// old-format and a current log) plus deterministic bit flips, cuts and splices either load with
// their good frames decoding, or fail with one stride::Error line.
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "tests/fuzz_log/log_fuzz_target.hpp"
#include "tests/fuzz_support/corpus.hpp"

namespace stride {
namespace {

std::string mutate(std::string s, std::mt19937_64& rng) {
  for (int k = 0, n = 1 + static_cast<int>(rng() % 4); k < n && !s.empty(); ++k) {
    const std::size_t at = rng() % s.size();
    switch (rng() % 4) {
      case 0:
        s[at] = static_cast<char>(s[at] ^ (1 << (rng() % 8)));
        break;
      case 1:
        s.resize(at);
        break;
      case 2:
        s.erase(at, 1 + rng() % 64);
        break;
      case 3:  // a copy of another stretch: duplicated frames, a frame inside a frame
        s.insert(at, s.substr(rng() % s.size(), rng() % 512));
        break;
    }
  }
  return s;
}

TEST(LogFuzz, DamagedLogsLoadWhatIsGoodOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_log/corpus");
  ASSERT_GE(seeds.size(), 2u);
  std::mt19937_64 rng(29);
  int decoded = 0;
  for (int i = 0; i < 1500; ++i) {
    const std::string input =
        i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds[rng() % seeds.size()], rng);
    ASSERT_NO_THROW(decoded += test::read_log_fuzz_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i;
  }
  EXPECT_GT(decoded, 1000);
}

}  // namespace
}  // namespace stride
