// The debug protocol's decoders under hostile input, in every (sanitized) test run: the committed
// corpus (every message kind, framing edge cases, type descriptions with values) plus
// deterministic mutations of it must decode or fail with one stride::Error line, in UTF-8.
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "robot/core/one_line.hpp"
#include "robot/core/utf8.hpp"
#include "tests/fuzz_debug/debug_fuzz_target.hpp"
#include "tests/fuzz_support/corpus.hpp"
#include "tests/fuzz_support/mutation.hpp"

namespace stride {
namespace {

std::string mutate(const std::string& s, std::mt19937_64& rng) {
  static const char* const kTokens[] = {"\xff\xff\xff\xff", "\xdd\xff\xff\xff\xff",
                                        "\xc4\xff",         "\x81\xa1t\xa3req",
                                        "\xcb\x7f\xf8",     "\x00",
                                        "\xde\xff\xff",     "\x0c"};
  return test::mutate(s, rng, kTokens);
}

TEST(DebugProtocolFuzz, CorpusAndMutationsDecodeOrFailWithOneLine) {
  const auto seeds = test::read_corpus("tests/fuzz_debug/corpus");
  ASSERT_GE(seeds.size(), 20u);
  std::mt19937_64 rng(11);
  std::size_t errors = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::string input =
        i < static_cast<int>(seeds.size()) ? seeds[i] : mutate(seeds[rng() % seeds.size()], rng);
    std::vector<std::string> messages;
    ASSERT_NO_THROW(messages = test::fuzz_debug_input(
                        reinterpret_cast<const std::uint8_t*>(input.data()), input.size()))
        << "input " << i;
    for (const auto& m : messages) {
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      EXPECT_FALSE(m.empty());
      EXPECT_TRUE(valid_utf8(m)) << one_line(m, 400);  // the peer's bad bytes escaped
    }
    errors += messages.size();
  }
  EXPECT_GT(errors, 20000u);  // most mutations are refused by most decoders
}

}  // namespace
}  // namespace stride
